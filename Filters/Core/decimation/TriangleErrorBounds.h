// What each extracted triangle is certified to: the bound e_t that the
// certified decimation starts from (CertifiedDecimation.h).
//
// The extraction proves, per surface cell C, a two-sided bound on the
// Hausdorff distance between the exact surface S in C and C's patch P_C:
// every point of P_C is within E_C of S (of S in C), and every point of S in
// C is within E_C of P_C. That is the bound the report's HausdorffBound is
// the largest of (Contour.cxx, DecideGuarantee):
// - an error-bounded cell: its certified E_C (CertifiedError.h), or its
//   diagonal where that is smaller or the certificate failed;
// - a plane-section cell or an exact cell: the finest cell's diagonal (their
//   patches lie on S up to rounding: PlanarCell.h, ExactCell.h);
// - any other surface or unresolved cell: its diagonal (patch and surface
//   both lie in the cell, and both are there: the cell's crossings are
//   points of S and of P_C).
// Giving each triangle of P_C the bound of its cell C then yields the two
// facts the decimation keeps true: (a) every point of triangle t is within
// e_t of S, and (b) every point s of S is within e_t of some triangle t (the
// cell holding s has a patch, and s is within E_C of it). A cell whose patch
// failed the exact embedding check (SplitReason PatchNotEmbedded) may have
// triangles leaving it, which the diagonal argument needs: its triangles get
// NaN, not proven (the guarantee is withdrawn there, and no decimation runs).
#pragma once

#include "AdaptiveOctree.h"
#include "SurfaceExtraction.h"

#include <vector>

namespace tpc
{

/// e_t for each triangle of `extraction.Mesh` (TriangleCell names its cell).
std::vector<double> TriangleErrorBounds(const AdaptiveOctree& tree, const ExtractionResult& extraction);

} // namespace tpc
