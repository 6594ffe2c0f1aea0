// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: radial basis functions.
//
// Every kernel is a function of the distance r scaled by a length R
// (xi = r/R). For the compactly supported Wendland functions R is the support
// radius (phi = 0 for xi >= 1, written (1 - xi)_+ = max(1 - xi, 0)); for the
// global kernels it is the shape length.
// Each kernel is a tiny struct with an inline operator()(r) and ofSquared(r^2)
// so that hot loops are instantiated per kernel (RadialKernel::visit) without
// a virtual call per evaluation. ofSquared avoids the square root where the
// formula allows it (TPS, Gaussian, IMQ) and the Wendland functions are written
// without branches, (1 - xi)_+ = (a + |a|)/2 with a = 1 - xi (exact in floating
// point), so that loops over them vectorize (std::max or a conditional here
// make GCC's SSE2 code two times slower). The array overloads
// ofSquared(r2, w) evaluate a whole block with Eigen's packet math (its
// SIMD sqrt, log and exp set no errno and vectorize without -ffast-math):
// 2x faster than the scalar loop for the Wendland functions with SSE2,
// 2-4x for every kernel with AVX.
#pragma once

#include "Types.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace dcprbf
{
namespace kernels
{

//- max(a, 0) without a branch: (a + |a|)/2, exact (2a and a/2 are exact)
inline double positivePart(double a)
{
    return 0.5*(a + std::abs(a));
}

//- Wendland C0: phi(xi) = (1 - xi)_+^2, compact, positive definite in R^3.
struct WendlandC0
{
    double invR;
    static constexpr bool compact = true;
    double operator()(double r) const
    {
        const double xi = r*invR;
        const double a = positivePart(1 - xi);
        return a*a;
    }
    double ofSquared(double r2) const { return (*this)(std::sqrt(r2)); }
    template<class Arr> void ofSquared(const Arr& r2, Arr& w) const
    {
        const Arr xi = r2.sqrt()*invR;
        const Arr a = (1 - xi).max(0.0);
        w = a.square();
    }
};

//- Wendland C2: phi(xi) = (1 - xi)_+^4 (4 xi + 1), compact, PD in R^3.
struct WendlandC2
{
    double invR;
    static constexpr bool compact = true;
    double operator()(double r) const
    {
        const double xi = r*invR;
        const double a = positivePart(1 - xi);
        const double a2 = a*a;
        return a2*a2*(4*xi + 1);
    }
    double ofSquared(double r2) const { return (*this)(std::sqrt(r2)); }
    template<class Arr> void ofSquared(const Arr& r2, Arr& w) const
    {
        const Arr xi = r2.sqrt()*invR;
        const Arr a = (1 - xi).max(0.0);
        w = a.square().square()*(4*xi + 1);
    }
};

//- Wendland C4: phi(xi) = (1 - xi)_+^6 (35/3 xi^2 + 6 xi + 1), compact, PD in R^3.
struct WendlandC4
{
    double invR;
    static constexpr bool compact = true;
    double operator()(double r) const
    {
        const double xi = r*invR;
        const double a = positivePart(1 - xi);
        const double a3 = a*a*a;
        return a3*a3*((35.0/3.0)*xi*xi + 6*xi + 1);
    }
    double ofSquared(double r2) const { return (*this)(std::sqrt(r2)); }
    template<class Arr> void ofSquared(const Arr& r2, Arr& w) const
    {
        const Arr xi = r2.sqrt()*invR;
        const Arr a = (1 - xi).max(0.0);
        w = (a*a*a).square()*(((35.0/3.0)*xi + 6)*xi + 1);
    }
};

//- Wendland C6: phi(xi) = (1 - xi)_+^8 (32 xi^3 + 25 xi^2 + 8 xi + 1),
//  compact, PD in R^3.
struct WendlandC6
{
    double invR;
    static constexpr bool compact = true;
    double operator()(double r) const
    {
        const double xi = r*invR;
        const double a = positivePart(1 - xi);
        const double a2 = a*a;
        const double a4 = a2*a2;
        return a4*a4*(((32*xi + 25)*xi + 8)*xi + 1);
    }
    double ofSquared(double r2) const { return (*this)(std::sqrt(r2)); }
    template<class Arr> void ofSquared(const Arr& r2, Arr& w) const
    {
        const Arr xi = r2.sqrt()*invR;
        const Arr a = (1 - xi).max(0.0);
        w = a.square().square().square()*(((32*xi + 25)*xi + 8)*xi + 1);
    }
};

//- Thin-plate spline: phi(xi) = xi^2 ln(xi), global, conditionally positive
//  definite of order 2: needs the linear polynomial.
struct ThinPlateSpline
{
    double invR;
    static constexpr bool compact = false;
    double operator()(double r) const
    {
        const double xi = r*invR;
        return xi > 0 ? xi*xi*std::log(xi) : 0.0;
    }
    //- xi^2 ln(xi) = xi^2 ln(xi^2)/2: no square root
    double ofSquared(double r2) const
    {
        const double xi2 = r2*invR*invR;
        return xi2 > 0 ? 0.5*xi2*std::log(xi2) : 0.0;
    }
    template<class Arr> void ofSquared(const Arr& r2, Arr& w) const
    {
        const Arr xi2 = r2*(invR*invR);
        // xi2 log(max(xi2, tiny)) is 0 at xi2 = 0 (no 0 log 0 = NaN)
        w = 0.5*xi2*xi2.max(std::numeric_limits<double>::min()).log();
    }
};

//- Gaussian: phi(xi) = exp(-xi^2), global, PD.
struct Gaussian
{
    double invR;
    static constexpr bool compact = false;
    double operator()(double r) const
    {
        const double xi = r*invR;
        return std::exp(-xi*xi);
    }
    double ofSquared(double r2) const { return std::exp(-r2*invR*invR); }
    template<class Arr> void ofSquared(const Arr& r2, Arr& w) const
    {
        w = (-(r2*(invR*invR))).exp();
    }
};

//- Inverse multiquadric: phi(xi) = 1/sqrt(1 + xi^2), global, PD.
struct InverseMultiquadric
{
    double invR;
    static constexpr bool compact = false;
    double operator()(double r) const
    {
        const double xi = r*invR;
        return 1.0/std::sqrt(1 + xi*xi);
    }
    double ofSquared(double r2) const
    {
        return 1.0/std::sqrt(1 + r2*invR*invR);
    }
    template<class Arr> void ofSquared(const Arr& r2, Arr& w) const
    {
        w = (1 + r2*(invR*invR)).sqrt().inverse();
    }
};

} // namespace kernels


//- A kernel chosen at run time: its type and its length R.
class RadialKernel
{
public:
    enum class Type
    {
        WendlandC0, WendlandC2, WendlandC4, WendlandC6,
        ThinPlateSpline, Gaussian, InverseMultiquadric
    };

    //- Construct from type and length R > 0 (throws Error otherwise)
    RadialKernel(Type type, double radius);

    //- Construct from a name (see names()); throws Error naming the
    //  allowed names for an unknown one
    static RadialKernel fromName(const std::string& name, double radius);

    //- The accepted names, in Type order
    static const std::vector<std::string>& names();

    const std::string& name() const;
    double radius() const { return radius_; }

    //- Zero beyond the radius?
    bool compact() const;

    //- Strictly positive definite (Cholesky applies)? TPS is only
    //  conditionally positive definite.
    bool positiveDefinite() const { return type_ != Type::ThinPlateSpline; }

    //- Needs the linear polynomial to give a solvable system?
    bool needsPolynomial() const { return type_ == Type::ThinPlateSpline; }

    //- Call f with the concrete kernel struct
    template<class F>
    decltype(auto) visit(F&& f) const
    {
        const double invR = 1.0/radius_;
        switch (type_)
        {
            case Type::WendlandC0: return f(kernels::WendlandC0{invR});
            case Type::WendlandC2: return f(kernels::WendlandC2{invR});
            case Type::WendlandC4: return f(kernels::WendlandC4{invR});
            case Type::WendlandC6: return f(kernels::WendlandC6{invR});
            case Type::ThinPlateSpline: return f(kernels::ThinPlateSpline{invR});
            case Type::Gaussian: return f(kernels::Gaussian{invR});
            default: return f(kernels::InverseMultiquadric{invR});
        }
    }

    //- phi(r): convenient, slower than visit() in a loop
    double operator()(double r) const
    {
        return visit([r](const auto& k) { return k(r); });
    }

private:
    Type type_;
    double radius_;
};

} // namespace dcprbf
