// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the vector width the quality kernels run at
// (AVX-512, AVX2 or the compiler's default vectors, chosen at run time from
// the processor; the values are the same at every width). The environment
// variable DCPRBF_SIMD_WIDTH caps it (e.g. 256: at most AVX2).
#pragma once

namespace dcprbf
{

class SimdWidth
{
public:
    //- The width in bits the wide kernels run at (512, 256 or 0: default)
    static unsigned bits();

    //- Cap the width at bits (>= 512: no cap; 256-511: AVX2; less: the
    //  default vectors)
    static void limit(unsigned bits);

    //- The cap (limit's last argument; at first DCPRBF_SIMD_WIDTH's)
    static unsigned cap();
};

} // namespace dcprbf
