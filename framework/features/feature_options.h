#pragma once
// How boundaries and creases are treated, whatever the scheme: OpenSubdiv's Sdc::Options.
// Every options struct that refines or analyses (RefineOptions, LimitOptions,
// SurfaceAnalysisOptions, ...) carries one FeatureOptions, so the choice is made once.
namespace subdiv {

// OpenSubdiv's Sdc::Options::VtxBoundaryInterpolation.
enum class BoundaryInterpolation { None, EdgesOnly, EdgesAndCorners };

// OpenSubdiv's Sdc::Options::CreasingMethod.
enum class CreaseMethod { Uniform, Chaikin };

struct FeatureOptions {
  BoundaryInterpolation boundary = BoundaryInterpolation::EdgesAndCorners;
  CreaseMethod crease_method = CreaseMethod::Uniform;
};

}  // namespace subdiv
