// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "SimdWidth.hpp"
#include "TetBatch.hpp"

namespace dcprbf
{

unsigned SimdWidth::bits()
{
    return detail::TetBatch::width();
}

void SimdWidth::limit(const unsigned bits)
{
    detail::TetBatch::limitWidth(bits);
}

unsigned SimdWidth::cap()
{
    return detail::TetBatch::widthCap();
}

} // namespace dcprbf
