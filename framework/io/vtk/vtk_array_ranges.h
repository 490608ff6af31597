#pragma once
// The value ranges VTK's XML writer puts into every array's header (RangeMin, RangeMax),
// computed on every core TBB may use and handed to VTK's range cache. Internal to io/.
//
// vtkXMLWriter asks each array for GetRange(-1); VTK computes it with vtkSMPTools, which in
// ParaView 5.11's build runs sequentially and took more time than compressing the arrays
// on a 16M-face level. VTK keeps a computed range in the array's information
// (vtkDataArray::PER_COMPONENT with COMPONENT_RANGE, L2_NORM_RANGE for vectors) until the
// array changes; ranges stored there the same way are what the writer then reads. The
// values are the same min and max VTK would find, so the file does not change.
#include <span>
#include <vector>

#include <vtkType.h>

class vtkDataArray;
class vtkPolyData;

namespace subdiv::io_detail {

// For the points, point, cell and field data and the cells' connectivity of `poly`; call
// when they are final (changing an array drops its range again). Arrays that hold a range
// already (store_array_range) keep it.
void cache_array_ranges(vtkPolyData& poly);

// `min` and `max` as `array`'s range: of its values (one component) or of its tuples' norms
// (several), known from elsewhere (validate_mesh_data's pass over the same values).
void store_array_range(vtkDataArray* array, double min, double max);

// For one array (doubles and integers of the kinds write_vtp makes; others are left to VTK).
void cache_array_range(vtkDataArray* array);

// For `array`, from `source` when both are views of the same values (the writer's copy of a
// cell array's connectivity shares its memory): the range cached for `source` instead of a
// second pass over the values; otherwise as cache_array_range.
void cache_array_range(vtkDataArray* array, vtkDataArray* source);

// For a one-component array that holds 0 everywhere but at `set` (positions, repeats
// allowed): its range from those values (and 0 if some position is not among them), without
// a pass over the zeros (write_vtp's sharpness, cell_kind and corner_sharpness arrays: 320 MB
// of zero pages on a 16M-face level). Arrays of other shapes as cache_array_range.
void cache_sparse_array_range(vtkDataArray* array, std::span<const vtkIdType> set);

}  // namespace subdiv::io_detail
