#pragma once
// Writes a mesh as .vtp with raw appended data, as ParaView and most VTK programs write it
// (`subdiv` itself writes inline binary): the input for tests of reading such files.
#include <filesystem>
#include <stdexcept>

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

#include "framework/io/vtk/vtk_output.h"
#include "framework/io/vtk/vtk_polydata.h"

namespace subdiv::test {

inline void write_appended_vtp(const std::filesystem::path& file, const MeshData& mesh) {
  OutputLevel level;
  level.mesh = &mesh;
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(io_detail::make_polydata(level));
  writer->SetFileName(file.c_str());
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToZLib();
  writer->SetHeaderTypeToUInt64();
  if (writer->Write() != 1) throw std::runtime_error("test: VTK could not write " + file.string());
}

}  // namespace subdiv::test
