#pragma once
// The SubdivKit plugin interface: the one header a plugin includes.
//
// A plugin is a shared library with one exported C function, `subdiv_plugin_info`, that
// returns a pointer to a small versioned record (the pattern of LLVM's pass plugins,
// llvmGetPassPluginInfo):
//
//   interface_version  SUBDIV_PLUGIN_INTERFACE_VERSION of the headers it was built with
//   name, version      the plugin's name (unique among loaded plugins) and its own version
//   subdivkit_version  the SubdivKit version of those headers (for messages)
//   register_plugin    called once with a PluginRegistry to fill (plugin_registry.h)
//
// SubdivKit reads interface_version first and refuses the plugin, without calling anything
// else in it, unless it equals its own. The record stays C-compatible and
// interface_version stays its first member in every future version, so even a plugin
// built for another interface is refused with a clear message rather than misread.
//
// Write the entry point with the macro:
//
//   #include "framework/plugin/plugin_api.h"
//   static void register_my_plugin(subdiv::PluginRegistry& registry) { ... }
//   SUBDIV_PLUGIN("my-plugin", "1.0.0", register_my_plugin)
//
// A plugin is native code running inside the `subdiv` process (or your program) with all
// its rights: load only plugins you trust. It must be built with a C++ compiler and
// standard library ABI compatible with SubdivKit's (the registry passes std::string,
// std::vector and std::function), which find_package(SubdivKit) + subdivkit_add_plugin()
// arrange.
#include <cstdint>

#include "framework/plugin/plugin_registry.h"

// Raised whenever anything a plugin sees changes incompatibly: this record, PluginRegistry,
// the specs it takes, or the engine types they expose (Level, ChildOrigins, SplitResult,
// FeatureContexts, RowWriter, ...).
#define SUBDIV_PLUGIN_INTERFACE_VERSION 3u  // 3: SplitterInfo::topology_reach, ring_scale (pieces)
// The SubdivKit release these headers belong to (checked against the build at compile
// time in plugin_loader.cpp).
#define SUBDIVKIT_VERSION_STRING "0.1.0"
// The exported symbol SubdivKit looks for.
#define SUBDIV_PLUGIN_ENTRY_POINT "subdiv_plugin_info"

extern "C" {

struct SubdivPluginInfo {
  std::uint32_t interface_version;
  const char* name;
  const char* version;
  const char* subdivkit_version;
  void (*register_plugin)(subdiv::PluginRegistry& registry);
};

// The entry point's type: SubdivKit calls it once after loading the library.
typedef const SubdivPluginInfo* (*SubdivPluginInfoFunction)(void);

}  // extern "C"

#if defined(_WIN32)
#define SUBDIV_PLUGIN_EXPORT extern "C" __declspec(dllexport)
#else
#define SUBDIV_PLUGIN_EXPORT extern "C" __attribute__((visibility("default")))
#endif

// Defines the entry point of a plugin named NAME (a string: letters, digits, '-', '_', '.'),
// version VERSION (a string), whose registration function is REGISTER.
#define SUBDIV_PLUGIN(NAME, VERSION, REGISTER)                                                   \
  SUBDIV_PLUGIN_EXPORT const SubdivPluginInfo* subdiv_plugin_info(void) {                         \
    static const SubdivPluginInfo info{SUBDIV_PLUGIN_INTERFACE_VERSION, NAME, VERSION,            \
                                       SUBDIVKIT_VERSION_STRING, REGISTER};                       \
    return &info;                                                                                 \
  }
