#pragma once
// OpenMesh .om files checked before OpenMesh reads them. Its OM reader trusts the file:
// chunk dimensions are only assert()ed (an abort in Debian's build), and halfedge, vertex
// and face ids go into the mesh unchecked, so a damaged file aborts the process or leaves a
// mesh whose face loops never close. This walks the chunks the way the reader will, checks
// every size against the file and every id against the elements, and follows every face's
// halfedge loop. Internal to io/.
#include <filesystem>
#include <string_view>

namespace subdiv::io_detail {

// Throws subdiv::Error "<file>: byte N: ..." naming the problem.
void check_om_bytes(const std::filesystem::path& file, std::string_view bytes);
void check_om_file(const std::filesystem::path& file);

}  // namespace subdiv::io_detail
