// Numbering of the corners, edges and faces of a cell, shared by the tests
// and the extraction.
//   corner c = x + 2y + 4z (bit a set: high side on axis a)
//   face f = 2 * axis + side; its in-plane axes are u = axis+1, v = axis+2 (mod 3)
//   edge e = 4 * axis + (du + 2 dv): the edge along `axis` at offsets du, dv on u, v
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

inline int EdgeAxis(int e)
{
  return e / 4;
}
/// Endpoint `end` (0: low, 1: high along the edge axis) of edge e.
inline int EdgeCorner(int e, int end)
{
  const int axis = EdgeAxis(e);
  const int r = e % 4;
  return ((r & 1) << UAxis(axis)) | (((r >> 1) & 1) << VAxis(axis)) | (end << axis);
}

inline bool Inside(unsigned mask, int corner)
{
  return ((mask >> corner) & 1u) != 0;
}

/// Signs alternate around some face (paper: face ambiguity, Fig. 3(b)).
inline bool HasFaceAmbiguity(unsigned mask)
{
  for (int f = 0; f < 6; ++f)
  {
    const bool s0 = Inside(mask, FaceCorner(f, 0)), s1 = Inside(mask, FaceCorner(f, 1));
    const bool s2 = Inside(mask, FaceCorner(f, 2)), s3 = Inside(mask, FaceCorner(f, 3));
    if (s0 == s2 && s1 == s3 && s0 != s1)
    {
      return true;
    }
  }
  return false;
}

/// Two diagonally opposite corners have one sign, the six others the other
/// (paper: voxel ambiguity, Fig. 2(d)).
inline bool HasVoxelAmbiguity(unsigned mask)
{
  for (int c = 0; c < 4; ++c)
  {
    const unsigned pair = (1u << c) | (1u << (7 - c));
    if (mask == pair || mask == (0xFFu & ~pair))
    {
      return true;
    }
  }
  return false;
}

inline bool FaceHasSignChange(unsigned mask, int f)
{
  const bool s0 = Inside(mask, FaceCorner(f, 0));
  for (int k = 1; k < 4; ++k)
  {
    if (Inside(mask, FaceCorner(f, k)) != s0)
    {
      return true;
    }
  }
  return false;
}
} // namespace cube
} // namespace tpc
