// Numbering of the corners and faces of a cell.
//   corner c = x + 2y + 4z (bit a set: high side on axis a)
//   face f = 2 * axis + side; its in-plane axes are u = axis+1, v = axis+2 (mod 3)
#pragma once

namespace tpc
{
namespace cube
{
inline int FaceAxis(int f)
{
  return f / 2;
}
inline int FaceSide(int f)
{
  return f % 2;
}
inline int UAxis(int axis)
{
  return (axis + 1) % 3;
}
inline int VAxis(int axis)
{
  return (axis + 2) % 3;
}

/// Corner k (0..3) of face f in cyclic order (0,0),(1,0),(1,1),(0,1) in (u, v).
inline int FaceCorner(int f, int k)
{
  static const int du[4] = { 0, 1, 1, 0 };
  static const int dv[4] = { 0, 0, 1, 1 };
  const int axis = FaceAxis(f);
  return (FaceSide(f) << axis) | (du[k] << UAxis(axis)) | (dv[k] << VAxis(axis));
}

} // namespace cube
} // namespace tpc
