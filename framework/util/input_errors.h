#pragma once
// Turning every exception that reading an input can raise into a subdiv::Error that names
// the file. Readers throw subdiv::Error for what they recognise; libraries underneath
// (OpenMesh, VTK, the standard library) can still throw std::length_error, std::bad_alloc,
// std::out_of_range and the like on inputs nobody foresaw, and "internal error:
// vector::_M_default_append" tells the user nothing.
#include <exception>
#include <new>
#include <string>
#include <utility>

#include "framework/util/error.h"

namespace subdiv {

// The message for a non-subdiv exception `e` met while reading `file`.
std::string unexpected_read_failure(const std::string& file, const std::exception& e);
// The message for running out of memory while reading `file` (the memory guard's words).
std::string read_out_of_memory(const std::string& file);

// Runs `read()` and returns its result; any exception but subdiv::Error becomes one that
// names `file`.
template <class Read>
auto naming_file_on_failure(const std::string& file, Read&& read) -> decltype(read()) {
  try {
    return std::forward<Read>(read)();
  } catch (const Error&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw Error(read_out_of_memory(file));
  } catch (const std::exception& e) {
    throw Error(unexpected_read_failure(file, e));
  }
}

}  // namespace subdiv
