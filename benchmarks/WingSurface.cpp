// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "WingSurface.hpp"

#include <cmath>
#include <random>

namespace dcprbf
{
namespace bench
{

namespace
{
constexpr double pi = 3.14159265358979323846;

double naca0012(double t)
{
    return 0.6*(0.2969*std::sqrt(t) - 0.1260*t - 0.3516*t*t
        + 0.2843*t*t*t - 0.1015*t*t*t*t);
}
}


Points Wing::surface(int nSpan, int nChord) const
{
    // nChord points per section: the leading edge, then (nChord - 1)/2
    // stations on each surface (nChord odd keeps it symmetric)
    const int half = (nChord - 1)/2;
    const int perSection = 1 + 2*half;
    Points p(nSpan*perSection, 3);
    const double tanSweep = std::tan(sweepDeg*pi/180);
    Eigen::Index k = 0;
    for (int s = 0; s < nSpan; ++s)
    {
        const double eta = double(s)/(nSpan - 1);
        const double y = eta*semiSpan;
        const double c = rootChord*(1 - (1 - taper)*eta);
        const double xLe = y*tanSweep;
        p.row(k++) << xLe, y, 0.0;
        for (int i = 1; i <= half; ++i)
        {
            const double t = 0.5*(1 - std::cos(pi*i/half));  // 0 < t <= 1
            const double z = c*naca0012(t);
            p.row(k++) << xLe + t*c, y, z;
            p.row(k++) << xLe + t*c, y, -z;
        }
    }
    return p;
}


Values Wing::displacement(const Points& x) const
{
    const double tanSweep = std::tan(sweepDeg*pi/180);
    Values d(x.rows(), 3);
    for (Eigen::Index i = 0; i < x.rows(); ++i)
    {
        const double eta = x(i, 1)/semiSpan;
        const double c = rootChord*(1 - (1 - taper)*eta);
        const double xq = x(i, 1)*tanSweep + 0.25*c;  // quarter chord
        const double th = -twistDeg*pi/180*eta;
        const double dx = x(i, 0) - xq;
        const double dz = x(i, 2);
        d(i, 0) = std::cos(th)*dx - std::sin(th)*dz - dx;
        d(i, 1) = 0;
        d(i, 2) = std::sin(th)*dx + std::cos(th)*dz - dz + bend*semiSpan*eta*eta;
    }
    return d;
}


Points Wing::volume(std::size_t n, unsigned seed) const
{
    std::mt19937 gen(seed);
    const double tanSweep = std::tan(sweepDeg*pi/180);
    std::uniform_real_distribution<double> ux(-rootChord, semiSpan*tanSweep + 2*rootChord);
    std::uniform_real_distribution<double> uy(0.0, 1.3*semiSpan);
    std::uniform_real_distribution<double> uz(-1.5*rootChord, 1.5*rootChord);
    Points p(n, 3);
    for (std::size_t i = 0; i < n; ++i) p.row(i) << ux(gen), uy(gen), uz(gen);
    return p;
}

} // namespace bench
} // namespace dcprbf
