#pragma once
// The lengths of a .vtp file's arrays, checked before VTK's XML reader allocates from them.
// vtkXMLReader sizes most arrays by a count it is told, not by the data, and allocates
// before it reads: points and point data by NumberOfPoints, cell data by the piece's
// cells, field data by NumberOfTuples, each cell section's offsets by its NumberOf...
// and its connectivity by the last offset's value (a last offset of 2^47 asked for 2^50
// bytes: found by fuzz_read_vtp). Here each array must hold the values it is sized for:
// binary arrays by the headers vtk_xml_blocks.h checked, ascii arrays by their digits; the
// last offset is read as VTK reads it (an input stream over the ascii text, or the one
// binary block that holds it). The allocations are then bounded by the file's data.
// Internal to io/.
#include <cstddef>
#include <filesystem>
#include <map>
#include <string_view>

#include "framework/io/vtk/vtk_xml_blocks.h"

namespace subdiv::io_detail {

// Throws subdiv::Error "<file>:<line>: ..." naming the array, what it needs and what it
// holds. `binary` is check_vtp_data_headers' result for the same bytes.
void check_vtp_array_lengths(const std::filesystem::path& file, std::string_view bytes,
                             const std::map<std::size_t, XmlArrayData>& binary);

}  // namespace subdiv::io_detail
