// Exact sign of a sum of products of doubles.
//
// Used only when an interval evaluation of a primitive at a lattice point
// cannot decide its sign: the sign of the field at grid corners must be the
// exact one, or two cells sharing a corner could disagree (Property 1 of the
// paper relies on corner signs). Shewchuk's expansion arithmetic (TwoSum,
// FMA TwoProduct, Grow-Expansion) is small and exact for the degree-2
// polynomials we evaluate, so a big-number library (GMP) is not needed.
// Overflow and gradual underflow are out of scope (coordinates are scaled to
// sane ranges by the adapters).
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace tpc
{

class ExactSum
{
public:
  void Add(double a) { this->Grow(a); }

  void AddProduct(double a, double b)
  {
    const double p = a * b;
    const double e = std::fma(a, b, -p);
    this->Grow(e);
    this->Grow(p);
  }

  void AddProduct(double a, double b, double c)
  {
    const double p1 = a * b;
    const double e1 = std::fma(a, b, -p1);
    this->AddProduct(p1, c);
    this->AddProduct(e1, c);
  }

  /// -1, 0 or +1: the exact sign of everything added so far.
  int Sign() const
  {
    for (std::size_t i = this->Components.size(); i-- > 0;)
    {
      if (this->Components[i] != 0.0)
      {
        return this->Components[i] > 0.0 ? 1 : -1;
      }
    }
    return 0;
  }

private:
  // Grow-Expansion with zero elimination: Components stays a nonoverlapping
  // expansion sorted by increasing magnitude whose exact sum is the total.
  void Grow(double b)
  {
    if (b == 0.0)
    {
      return;
    }
    double q = b;
    std::size_t out = 0;
    for (std::size_t i = 0; i < this->Components.size(); ++i)
    {
      const double e = this->Components[i];
      const double s = q + e;
      const double bb = s - q;
      const double h = (q - (s - bb)) + (e - bb);
      q = s;
      if (h != 0.0)
      {
        this->Components[out++] = h;
      }
    }
    this->Components.resize(out);
    if (q != 0.0)
    {
      this->Components.push_back(q);
    }
  }

  std::vector<double> Components;
};

} // namespace tpc
