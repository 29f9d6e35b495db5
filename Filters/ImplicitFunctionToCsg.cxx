#include "ImplicitFunctionToCsg.h"

#include "vtkAbstractTransform.h"
#include "vtkBox.h"
#include "vtkCylinder.h"
#include "vtkImplicitBoolean.h"
#include "vtkImplicitFunction.h"
#include "vtkImplicitFunctionCollection.h"
#include "vtkLinearTransform.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPlane.h"
#include "vtkQuadric.h"
#include "vtkSphere.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace tpc
{
namespace vtkadapter
{
namespace
{
using Matrix = std::array<double, 16>;

Matrix Identity()
{
  return { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
}

Matrix Multiply(const Matrix& a, const Matrix& b)
{
  Matrix r{};
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      for (int k = 0; k < 4; ++k)
      {
        r[4 * i + j] += a[4 * i + k] * b[4 * k + j];
      }
    }
  }
  return r;
}

bool IsIdentity(const Matrix& m)
{
  return m == Identity();
}

class Converter
{
public:
  PrimitiveSet& Primitives;
  std::string& Error;

  int Add(const Quadric& q, const Matrix& toLocal)
  {
    this->Primitives.Quadrics.push_back(IsIdentity(toLocal) ? q : q.Composed(toLocal.data()));
    return static_cast<int>(this->Primitives.Quadrics.size() - 1);
  }

  /// `toParent` maps world points to the input space of this function's parent.
  bool Convert(vtkImplicitFunction* f, const Matrix& toParent, CsgTerm& term)
  {
    if (!f)
    {
      this->Error = "a null implicit function was found in the tree";
      return false;
    }
    Matrix toLocal;
    if (!this->ComposeTransform(f, toParent, toLocal))
    {
      return false;
    }
    if (auto* b = vtkImplicitBoolean::SafeDownCast(f))
    {
      return this->ConvertBoolean(b, toLocal, term);
    }
    if (auto* s = vtkSphere::SafeDownCast(f))
    {
      term = CsgTerm::Primitive(this->Add(
        Quadric::Sphere({ s->GetCenter()[0], s->GetCenter()[1], s->GetCenter()[2] }, s->GetRadius()),
        toLocal));
      return true;
    }
    if (auto* q = vtkQuadric::SafeDownCast(f))
    {
      std::array<double, 10> c;
      std::copy(q->GetCoefficients(), q->GetCoefficients() + 10, c.begin());
      term = CsgTerm::Primitive(this->Add(Quadric(c), toLocal));
      return true;
    }
    if (auto* c = vtkCylinder::SafeDownCast(f))
    {
      const double* ctr = c->GetCenter();
      const double* ax = c->GetAxis();
      term = CsgTerm::Primitive(this->Add(
        Quadric::Cylinder({ ctr[0], ctr[1], ctr[2] }, { ax[0], ax[1], ax[2] }, c->GetRadius()), toLocal));
      return true;
    }
    if (auto* p = vtkPlane::SafeDownCast(f))
    {
      return this->ConvertPlane(p, toLocal, term);
    }
    if (auto* box = vtkBox::SafeDownCast(f))
    {
      return this->ConvertBox(box, toLocal, term);
    }
    this->Error = std::string("implicit functions of class ") + f->GetClassName() +
      " are not supported; use vtkSphere, vtkQuadric, vtkBox, vtkCylinder, vtkPlane or a "
      "vtkImplicitBoolean of them";
    return false;
  }

  /// vtkImplicitFunction::FunctionValue evaluates EvaluateFunction(T x):
  /// this function's own (affine) transform composed after the parent's.
  bool ComposeTransform(vtkImplicitFunction* f, const Matrix& toParent, Matrix& toLocal)
  {
    toLocal = toParent;
    vtkAbstractTransform* t = f->GetTransform();
    if (!t)
    {
      return true;
    }
    auto* linear = vtkLinearTransform::SafeDownCast(t);
    if (!linear)
    {
      this->Error = std::string("the Transform of a ") + f->GetClassName() + " is a " + t->GetClassName() +
        "; only linear transforms (e.g. vtkTransform) are supported";
      return false;
    }
    Matrix m;
    vtkMatrix4x4* vm = linear->GetMatrix();
    for (int i = 0; i < 4; ++i)
    {
      for (int j = 0; j < 4; ++j)
      {
        m[4 * i + j] = vm->GetElement(i, j);
      }
    }
    if (m[12] != 0.0 || m[13] != 0.0 || m[14] != 0.0 || m[15] != 1.0)
    {
      this->Error = "a projective Transform on a " + std::string(f->GetClassName()) +
        " is not supported; use an affine vtkTransform";
      return false;
    }
    toLocal = Multiply(m, toParent);
    return true;
  }

  /// The plane read back from the function itself rather than from Origin and
  /// Normal: ParaView's vtkPVPlane (the Plane widget) adds an Offset along the
  /// normal and may snap the normal to an axis. Both are affine: the gradient
  /// is the normal, and f(origin) / |n|^2 the offset.
  bool ConvertPlane(vtkPlane* p, const Matrix& toLocal, CsgTerm& term)
  {
    double o[3] = { p->GetOrigin()[0], p->GetOrigin()[1], p->GetOrigin()[2] };
    double n[3];
    p->EvaluateGradient(o, n);
    const double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    if (!(nn > 0.0))
    {
      this->Error = "a vtkPlane has a zero normal";
      return false;
    }
    const double shift = p->EvaluateFunction(o) / nn;
    const Vec3 point(o[0] - shift * n[0], o[1] - shift * n[1], o[2] - shift * n[2]);
    term = CsgTerm::Primitive(this->Add(Quadric::Plane(point, { n[0], n[1], n[2] }), toLocal));
    return true;
  }

  bool ConvertBoolean(vtkImplicitBoolean* b, const Matrix& toLocal, CsgTerm& term)
  {
    CsgTerm::Op op;
    switch (b->GetOperationType())
    {
      case vtkImplicitBoolean::VTK_UNION:
        op = CsgTerm::Op::Union;
        break;
      case vtkImplicitBoolean::VTK_INTERSECTION:
        op = CsgTerm::Op::Intersection;
        break;
      case vtkImplicitBoolean::VTK_DIFFERENCE:
        op = CsgTerm::Op::Difference;
        break;
      default:
        this->Error = "vtkImplicitBoolean with UnionOfMagnitudes does not describe a solid; use "
                      "Union, Intersection or Difference";
        return false;
    }
    std::vector<CsgTerm> operands;
    vtkImplicitFunctionCollection* list = b->GetFunction();
    list->InitTraversal();
    while (vtkImplicitFunction* child = list->GetNextItem())
    {
      CsgTerm t;
      if (!this->Convert(child, toLocal, t))
      {
        return false;
      }
      operands.push_back(std::move(t));
    }
    if (operands.empty())
    {
      this->Error = "a vtkImplicitBoolean has no functions";
      return false;
    }
    term = CsgTerm::Combine(op, std::move(operands));
    return true;
  }

  bool ConvertBox(vtkBox* box, const Matrix& toLocal, CsgTerm& term)
  {
    double b[6];
    box->GetBounds(b);
    std::vector<CsgTerm> planes;
    for (int a = 0; a < 3; ++a)
    {
      Vec3 n, o;
      n[a] = 1.0;
      o[a] = b[2 * a + 1];
      planes.push_back(CsgTerm::Primitive(this->Add(Quadric::Plane(o, n), toLocal)));
      n[a] = -1.0;
      o[a] = b[2 * a];
      planes.push_back(CsgTerm::Primitive(this->Add(Quadric::Plane(o, n), toLocal)));
    }
    term = CsgTerm::Combine(CsgTerm::Op::Intersection, std::move(planes));
    // Bounds of the (possibly rotated) box: its corners mapped back to world.
    vtkNew<vtkMatrix4x4> m, inv;
    for (int i = 0; i < 4; ++i)
    {
      for (int j = 0; j < 4; ++j)
      {
        m->SetElement(i, j, toLocal[4 * i + j]);
      }
    }
    if (m->Determinant() != 0.0 && b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5])
    {
      vtkMatrix4x4::Invert(m, inv);
      SolidBounds hint = SolidBounds::Nothing();
      for (int c = 0; c < 8; ++c)
      {
        const double local[4] = { b[(c & 1) ? 1 : 0], b[(c & 2) ? 3 : 2], b[(c & 4) ? 5 : 4], 1.0 };
        double world[4];
        inv->MultiplyPoint(local, world);
        SolidBounds corner;
        corner.Box = { { world[0], world[1], world[2] }, { world[0], world[1], world[2] } };
        hint = SolidBounds::Hull(hint, corner);
      }
      for (int a = 0; a < 3; ++a)
      {
        const double pad = 1e-9 * (hint.Box.hi[a] - hint.Box.lo[a]) + 1e-12 * std::fabs(hint.Box.hi[a]);
        hint.Box.lo[a] -= pad;
        hint.Box.hi[a] += pad;
      }
      term.HasBoundsHint = true;
      term.BoundsHint = hint;
    }
    return true;
  }
};
} // namespace

bool ConvertImplicitFunction(vtkImplicitFunction* function, PrimitiveSet& primitives,
  CsgTerm& term, std::string& error)
{
  Converter c{ primitives, error };
  return c.Convert(function, Identity(), term);
}

int CountSignDisagreements(vtkImplicitFunction* function, const PrimitiveSet& primitives,
  const CsgTerm& term, const Box3& box, int samples)
{
  const CsgExpressionPtr expression = CsgExpression::FromTerm(term);
  if (!expression)
  {
    return 0;
  }
  std::vector<std::pair<Vec3, double>> values;
  double scale = 0.0;
  std::uint64_t state = 0x9E3779B97F4A7C15ULL;
  auto next = [&]() {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  for (int i = 0; i < samples; ++i)
  {
    Vec3 p;
    for (int a = 0; a < 3; ++a)
    {
      p[a] = box.lo[a] + next() * (box.hi[a] - box.lo[a]);
    }
    double x[3] = { p[0], p[1], p[2] };
    const double v = function->FunctionValue(x);
    values.emplace_back(p, v);
    if (std::isfinite(v))
    {
      scale = std::max(scale, std::fabs(v));
    }
  }
  int disagreements = 0;
  for (const auto& pv : values)
  {
    if (!std::isfinite(pv.second) || std::fabs(pv.second) <= 1e-7 * scale)
    {
      continue;
    }
    if ((pv.second < 0.0) != expression->IsInside(pv.first, primitives))
    {
      ++disagreements;
    }
  }
  return disagreements;
}

} // namespace vtkadapter
} // namespace tpc
