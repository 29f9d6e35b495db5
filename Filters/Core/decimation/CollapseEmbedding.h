// Whether a collapse keeps the surface embedded and the same solid's
// boundary (CertifiedDecimation.h, Embedding): its made triangles meet no
// other triangle improperly, and the pocket between its star and the made
// triangles holds no other part of the surface. Both exact.
#pragma once

#include "LiveSurface.h"

namespace tpc
{

/// Does a made triangle meet another made one, or a live triangle outside
/// the star, other than in the vertices and edge they share?
bool MeetsAnother(const LiveSurface& surface, const Collapse& c, VisitMarks& marks);

/// Does the pocket between the star and the made triangles - the closed
/// tetrahedra (From, To, a, b) over the made triangles' far edges ab -
/// hold a vertex of another live triangle (a link vertex tested against
/// the tetrahedra it is not a corner of), or all the rest of the star's
/// component - which then has no vertex outside the star's box - turned
/// inside out (its enclosed volume changes sign, or cannot be told)?
bool SweepsOverAnother(const LiveSurface& surface, const Collapse& c, VisitMarks& marks);

} // namespace tpc
