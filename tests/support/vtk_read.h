#pragma once
// Reading the tool's .vtp output back with VTK, for end-to-end tests.
#include <filesystem>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

namespace subdiv::test {

inline vtkSmartPointer<vtkPolyData> read_vtp(const std::filesystem::path& file) {
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  return reader->GetOutput();
}

}  // namespace subdiv::test
