#pragma once
// Text that goes into VTK XML attributes (array names, .pvd file names). VTK's writer puts
// names between quotes as they are, so a '"', '<' or '&' in a name made the file malformed
// XML, and a newline was read back as a space (XML attribute normalisation). Internal to io/.
#include <string>
#include <string_view>

namespace subdiv::io_detail {

// `text` with &, <, >, " as entities and tab, newline, carriage return as character
// references, so that an XML parser gives back exactly `text`.
std::string xml_attribute_text(std::string_view text);

// Throws subdiv::Error "<context>: <what> '<text>' ..." if XML 1.0 cannot hold `text` at all:
// control characters other than tab, newline and carriage return, or bytes that are not UTF-8.
void require_xml_text(std::string_view text, std::string_view what, std::string_view context);

}  // namespace subdiv::io_detail
