#pragma once
// .vtp files checked before VTK's XML reader sees them: the piece sizes it allocates from
// (NumberOfPoints="2000000000") must be whole numbers that SubdivKit's 32-bit indices hold
// and whose arrays fit in the memory this process may use; arrays must have a sane number
// of components. VTK would otherwise throw std::length_error or std::bad_alloc, or take
// the machine's memory. Internal to io/.
#include <filesystem>
#include <string_view>

namespace subdiv::io_detail {

// Throws subdiv::Error "<file>:<line>: ..." naming the attribute and the fix.
void check_vtp_text(const std::filesystem::path& file, std::string_view bytes);
void check_vtp_file(const std::filesystem::path& file);

}  // namespace subdiv::io_detail
