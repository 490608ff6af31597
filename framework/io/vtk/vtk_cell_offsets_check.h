#pragma once
// The cell offsets of a .vtp file, checked before VTK's XML reader allocates from them.
// vtkXMLUnstructuredDataReader sizes each cell section's connectivity by the last value of
// its offsets array and allocates that many ids before it reads them: a last offset of 2^47
// asked for 2^50 bytes (found by fuzz_read_vtp). Here that value is read as VTK reads it
// (ascii text, or binary data through the headers vtk_xml_blocks.h checked) and must not
// exceed the values the section's connectivity array holds. Internal to io/.
#include <cstddef>
#include <filesystem>
#include <map>
#include <string_view>

#include "framework/io/vtk/vtk_xml_blocks.h"

namespace subdiv::io_detail {

// Throws subdiv::Error "<file>:<line>: ..." naming the section, the last offset and the
// connectivity's length. `binary` is check_vtp_data_headers' result for the same bytes.
void check_vtp_cell_offsets(const std::filesystem::path& file, std::string_view bytes,
                            const std::map<std::size_t, XmlArrayData>& binary);

}  // namespace subdiv::io_detail
