#pragma once
// VTK prints what goes wrong to its global output window (the terminal, with ANSI colours,
// source file names, object addresses and vtkInformation dumps) unless an observer takes
// it. While a VtkMessageCapture lives, everything VTK would print is collected instead, so
// that readers can put the gist into their own message that names the user's file.
// Internal to io/.
#include <string>

namespace subdiv::io_detail {

class VtkMessageCapture {
public:
  VtkMessageCapture();
  ~VtkMessageCapture();
  VtkMessageCapture(const VtkMessageCapture&) = delete;
  VtkMessageCapture& operator=(const VtkMessageCapture&) = delete;

  // The first message VTK gave, made readable (see vtk_readable_message); empty if none.
  std::string first_message() const;
  // The first error (not warning) VTK gave; empty if none.
  std::string first_error() const;

private:
  struct Impl;
  Impl* impl_;
};

// "ERROR: In /build/vtk/IO/XML/vtkXMLReader.cxx, line 12\nvtkXMLPolyDataReader (0x55d1):
// what went wrong\n\n" -> "what went wrong": no source file, no address, one line, no
// control characters, at most a few hundred characters.
std::string vtk_readable_message(std::string message);

}  // namespace subdiv::io_detail
