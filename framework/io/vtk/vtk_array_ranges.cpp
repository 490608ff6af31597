#include "framework/io/vtk/vtk_array_ranges.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationDoubleVectorKey.h>
#include <vtkInformationInformationVectorKey.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkType.h>

namespace subdiv::io_detail {
namespace {

struct Range {
  double min = std::numeric_limits<double>::max(), max = std::numeric_limits<double>::lowest();
  Range join(const Range& o) const { return {std::min(min, o.min), std::max(max, o.max)}; }
};

// The norm of a tuple whose squares overflow (coordinates beyond 1e154), computed scaled by
// the largest magnitude and clamped to the largest double: a file's RangeMax of "inf" is
// unreadable for SubdivKit and ParaView alike (the XML reader refuses it).
template <typename T>
double scaled_norm(const T* tuple, int components) {
  double scale = 0;
  for (int c = 0; c < components; ++c) scale = std::max(scale, std::abs(double(tuple[c])));
  if (!std::isfinite(scale)) return std::numeric_limits<double>::max();
  double sum = 0;
  for (int c = 0; c < components; ++c) sum += (double(tuple[c]) / scale) * (double(tuple[c]) / scale);
  return std::min(scale * std::sqrt(sum), std::numeric_limits<double>::max());
}

// Over `tuples` tuples of `components` values: of the values (one component) or of the
// tuples' Euclidean norms (several), as vtkDataArray::GetRange(-1) defines it. NaN is
// skipped, as VTK skips it.
template <typename T>
Range range_of(const T* values, std::size_t tuples, int components) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, tuples, 1 << 16), Range{},
      [&](const tbb::blocked_range<std::size_t>& r, Range range) {
        if (components == 1) {  // apart, so that the compiler vectorises it
          T lo = std::numeric_limits<T>::max(), hi = std::numeric_limits<T>::lowest();
          for (std::size_t t = r.begin(); t != r.end(); ++t) {
            lo = values[t] < lo ? values[t] : lo;  // false for NaN: skipped
            hi = values[t] > hi ? values[t] : hi;
          }
          return lo > hi ? range : range.join({double(lo), double(hi)});  // lo > hi: only NaN
        }
        for (std::size_t t = r.begin(); t != r.end(); ++t) {
          double v = 0;
          {
            for (int c = 0; c < components; ++c) {
              const double x = double(values[t * std::size_t(components) + std::size_t(c)]);
              v += x * x;
            }
            v = std::sqrt(v);
            if (std::isinf(v)) v = scaled_norm(values + t * std::size_t(components), components);
          }
          if (v < range.min) range.min = v;
          if (v > range.max) range.max = v;
        }
        return range;
      },
      [](const Range& a, const Range& b) { return a.join(b); });
}

// The largest magnitude a range may have: VTK writes ranges with 11 significant digits, and
// the largest double, 1.7976931348623157e308, printed so (1.7976931349e+308) reads back
// as inf, which makes VTK's reader refuse the file. A range is metadata: clamped, not refused.
constexpr double kLargestWrittenRange = 1.797693134e308;

// Likewise below: a subnormal bound (a norm of 1e-320) parses with ERANGE, which a C++
// stream (libstdc++'s num_get) takes for a failure, and VTK parses with streams. Such a bound
// moves outwards to 0 or to just above the smallest normal double, so that the range still
// holds every value.
constexpr double kSmallestWrittenRange = 2.2250738586e-308;

double clamped_min(double x) {
  if (std::abs(x) >= kSmallestWrittenRange || x == 0) return std::clamp(x, -kLargestWrittenRange, kLargestWrittenRange);
  return x < 0 ? -kSmallestWrittenRange : 0.0;
}

double clamped_max(double x) {
  if (std::abs(x) >= kSmallestWrittenRange || x == 0) return std::clamp(x, -kLargestWrittenRange, kLargestWrittenRange);
  return x > 0 ? kSmallestWrittenRange : 0.0;
}

void store(vtkDataArray& array, const Range& range) {
  const double values[2] = {clamped_min(range.min), clamped_max(range.max)};
  vtkInformation* info = array.GetInformation();
  if (array.GetNumberOfComponents() == 1) {
    vtkNew<vtkInformationVector> per_component;
    per_component->SetNumberOfInformationObjects(1);
    per_component->GetInformationObject(0)->Set(vtkDataArray::COMPONENT_RANGE(), values, 2);
    info->Set(vtkDataArray::PER_COMPONENT(), per_component);
  } else {
    info->Set(vtkDataArray::L2_NORM_RANGE(), values, 2);
  }
}

bool has_range(vtkDataArray& array) {
  vtkInformation* info = array.HasInformation() ? array.GetInformation() : nullptr;
  if (!info) return false;
  if (array.GetNumberOfComponents() != 1) return info->Has(vtkDataArray::L2_NORM_RANGE());
  vtkInformationVector* per_component = info->Get(vtkDataArray::PER_COMPONENT());
  return per_component && per_component->GetNumberOfInformationObjects() > 0 &&
         per_component->GetInformationObject(0)->Has(vtkDataArray::COMPONENT_RANGE());
}

}  // namespace

void store_array_range(vtkDataArray* array, double min, double max) {
  if (array) store(*array, {min, max});
}

void cache_array_range(vtkDataArray* array) {
  if (!array || !array->HasStandardMemoryLayout() || array->GetNumberOfTuples() == 0) return;
  const std::size_t tuples = std::size_t(array->GetNumberOfTuples());
  const int components = array->GetNumberOfComponents();
  const void* data = array->GetVoidPointer(0);
  switch (array->GetDataType()) {  // the types write_vtp makes; VTK computes the others
    case VTK_DOUBLE: store(*array, range_of(static_cast<const double*>(data), tuples, components)); break;
    case VTK_INT: store(*array, range_of(static_cast<const int*>(data), tuples, components)); break;
    case VTK_UNSIGNED_CHAR: store(*array, range_of(static_cast<const unsigned char*>(data), tuples, components)); break;
    case VTK_ID_TYPE: store(*array, range_of(static_cast<const vtkIdType*>(data), tuples, components)); break;
    case VTK_LONG: store(*array, range_of(static_cast<const long*>(data), tuples, components)); break;
    case VTK_LONG_LONG: store(*array, range_of(static_cast<const long long*>(data), tuples, components)); break;
    default: break;
  }
}

void cache_array_range(vtkDataArray* array, vtkDataArray* source) {
  const bool same_values = array && source && array->HasStandardMemoryLayout() && source->HasStandardMemoryLayout() &&
                           array->GetNumberOfTuples() > 0 && array->GetDataType() == source->GetDataType() &&
                           array->GetNumberOfTuples() == source->GetNumberOfTuples() &&
                           array->GetNumberOfComponents() == source->GetNumberOfComponents() &&
                           array->GetVoidPointer(0) == source->GetVoidPointer(0);
  if (!same_values) return cache_array_range(array);
  double range[2];
  source->GetRange(range, array->GetNumberOfComponents() == 1 ? 0 : -1);  // VTK's cache: cache_array_ranges
  store(*array, {range[0], range[1]});
}

void cache_sparse_array_range(vtkDataArray* array, std::span<const vtkIdType> set) {
  if (!array || array->GetNumberOfComponents() != 1 || array->GetNumberOfTuples() == 0) return cache_array_range(array);
  Range range;
  for (vtkIdType i : set) {
    const double v = array->GetComponent(i, 0);
    if (v == v) range = range.join({v, v});  // NaN skipped, as VTK skips it
  }
  // Fewer positions than values: some value is one of the zeros (repeats only make it surer).
  if (vtkIdType(set.size()) < array->GetNumberOfTuples()) range = range.join({0.0, 0.0});
  else return cache_array_range(array);  // every value may be set: the values decide
  store(*array, range);
}

namespace {

void cache_unless_known(vtkDataArray* array) {
  if (array && !has_range(*array)) cache_array_range(array);
}

void cache(vtkFieldData* data) {
  if (!data) return;
  for (int i = 0; i < data->GetNumberOfArrays(); ++i) cache_unless_known(data->GetArray(i));
}

}  // namespace

void cache_array_ranges(vtkPolyData& poly) {
  if (poly.GetPoints()) cache_unless_known(poly.GetPoints()->GetData());
  cache(poly.GetPointData());
  cache(poly.GetCellData());
  cache(poly.GetFieldData());
  for (vtkCellArray* cells : {poly.GetVerts(), poly.GetLines(), poly.GetStrips(), poly.GetPolys()})
    if (cells) cache_unless_known(cells->GetConnectivityArray());
}

}  // namespace subdiv::io_detail
