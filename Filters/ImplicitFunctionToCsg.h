// Adapter: a vtkImplicitFunction tree -> the core's primitives and CSG term.
//
// Supported: vtkSphere, vtkQuadric, vtkBox (six planes), vtkCylinder,
// vtkPlane and vtkImplicitBoolean (union, intersection, difference) trees of
// them, each with an optional linear Transform. Everything else is refused
// with a message rather than approximated.
#ifndef ImplicitFunctionToCsg_h
#define ImplicitFunctionToCsg_h

#include "CsgExpression.h"

#include <string>
#include <vector>

class vtkImplicitFunction;

namespace tpc
{
namespace vtkadapter
{

/// Appends the function's primitives to `primitives` and returns its term in
/// `term`. On failure returns false and explains why in `error`.
bool ConvertImplicitFunction(vtkImplicitFunction* function, PrimitiveSet& primitives,
  CsgTerm& term, std::string& error);

/// Compares the signs of the VTK function and of the converted scene at
/// pseudo-random points of `box` (skipping points where the VTK value is
/// within rounding of zero). Catches subclasses that override evaluation in
/// ways the converter does not know. Returns the number of disagreements.
int CountSignDisagreements(vtkImplicitFunction* function, const PrimitiveSet& primitives,
  const CsgTerm& term, const Box3& box, int samples = 256);

} // namespace vtkadapter
} // namespace tpc

#endif
