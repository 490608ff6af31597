#pragma once
// The line where the value at a JSON path ("steps[1].rules.edge[0].w") starts in JSON
// text, so messages about a parsed document can name a line an editor jumps to. The JSON
// library keeps no positions; this walks the text along the path only.
#include <string>
#include <string_view>

namespace subdiv {

// 1-based line of the value at `path` in `text`, or 0 when the path is not in the text
// (or the text is not JSON the walk understands).
int json_path_line(std::string_view text, std::string_view path);

// "FILE: path: message" with the path's line inserted ("FILE:LINE: path: message") when
// `message` starts with `label` + ": " and the path is found in `text`; else unchanged.
std::string with_json_line(const std::string& message, const std::string& label, std::string_view text);

}  // namespace subdiv
