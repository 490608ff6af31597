#pragma once
// The Scheme drop-down's list, as the string array both filters' information property
// "SchemeNames" hands to ParaView.
#include <exception>
#include <string>

#include <vtkStringArray.h>

#include "scheme_choice.h"

namespace subdiv::paraview {

// Fills `names` with every registered surface scheme; returns why not when listing fails
// (a scheme directory that cannot be read), for the filter's error message.
inline std::string fill_scheme_names(vtkStringArray& names) {
  names.Initialize();
  try {
    for (const std::string& name : surface_scheme_names()) names.InsertNextValue(name);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace subdiv::paraview
