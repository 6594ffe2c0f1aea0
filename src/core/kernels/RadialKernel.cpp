// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "RadialKernel.hpp"

#include <sstream>

namespace dcprbf
{

RadialKernel::RadialKernel(Type type, double radius)
:
    type_(type),
    radius_(radius)
{
    if (!(radius > 0) || !std::isfinite(radius))
    {
        std::ostringstream os;
        os << "kernel radius must be positive and finite, got " << radius;
        throw Error(os.str());
    }
}


const std::vector<std::string>& RadialKernel::names()
{
    static const std::vector<std::string> n
    {
        "WendlandC0", "WendlandC2", "WendlandC4", "WendlandC6",
        "TPS", "Gaussian", "IMQ"
    };
    return n;
}


RadialKernel RadialKernel::fromName(const std::string& name, double radius)
{
    const auto& n = names();
    for (std::size_t i = 0; i < n.size(); ++i)
    {
        if (n[i] == name)
        {
            return RadialKernel(static_cast<Type>(i), radius);
        }
    }
    std::ostringstream os;
    os << "unknown radial basis function '" << name << "'; allowed:";
    for (const auto& s : n) os << ' ' << s;
    throw Error(os.str());
}


const std::string& RadialKernel::name() const
{
    return names()[static_cast<std::size_t>(type_)];
}


bool RadialKernel::compact() const
{
    return visit([](const auto& k) { return k.compact; });
}

} // namespace dcprbf
