#pragma once
// How PLY's scalar properties map to named arrays, both ways, after the conventions of the
// tools that write PLY (MeshLab, Blender, CloudCompare): nx ny nz are normals; red green
// blue [alpha] a colour; s t (or u v, texture_u texture_v) texture coordinates;
// name_0 name_1 ... the components of one array `name`; any other property is an array of
// its own.
#include <string>
#include <vector>

#include "framework/io/mesh_data.h"

namespace subdiv::io_detail {

struct PropertyGroup {
  std::string name;
  ArrayRole role = ArrayRole::Data;
  std::vector<int> properties;  // indices into the element's property list, one per component
};

// The arrays a PLY element's scalar properties form. `names[i]` is property i's name; the
// indices in `skip` (x, y, z, list properties) take part in none.
std::vector<PropertyGroup> group_properties(const std::vector<std::string>& names, const std::vector<bool>& skip);

// The property names an array is written with (the inverse of group_properties).
std::vector<std::string> property_names(const DataArray& array);

// The property names each of `arrays` is written with, such that the PLY header holds them:
// one word of printable ASCII, distinct from each other and from `taken` (x y z, or
// vertex_indices). A name that breaks this (a space, a newline that would forge a header
// line, a point array "x") is renamed; `notes` gets one line per renamed array for the
// header's comments, "<what> array '<name>' written as '<new name>'".
std::vector<std::vector<std::string>> writable_property_names(const std::vector<DataArray>& arrays,
                                                              std::vector<std::string> taken, const char* what,
                                                              std::vector<std::string>& notes);

}  // namespace subdiv::io_detail
