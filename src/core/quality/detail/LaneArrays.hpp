// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the storage of a SIMD batch (TetBatch, PrismBatch,
// PlanarMapBatch): nIn input and nOut output components of n items, each
// component contiguous over the items (structure of arrays), stride() apart.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace dcprbf
{
namespace detail
{

class LaneArrays
{
public:
    LaneArrays(const int nIn, const int nOut) : nIn_(nIn), nOut_(nOut) {}

    //- Room for n items (their values undefined until set); the room only
    //  grows (rounded up to a multiple of 8 items, and off a multiple of
    //  64: components a power of two apart share cache sets, and a batch's
    //  dozens of components then evict each other)
    void resize(const std::size_t n)
    {
        n_ = n;
        if (n > stride_)
        {
            stride_ = (std::max(n, 2*stride_) + 7)/8*8;
            stride_ += stride_ % 64 == 0 ? 8 : 0;
            in_.assign(std::size_t(nIn_)*stride_, 0.0);
            out_.assign(std::size_t(nOut_)*stride_, 0.0);
        }
    }

    std::size_t size() const { return n_; }
    std::size_t stride() const { return stride_; }

    //- Input component k of item t
    double& in(const int k, const std::size_t t) { return in_[std::size_t(k)*stride_ + t]; }

    //- Output component k of item t
    double out(const int k, const std::size_t t) const
    {
        return out_[std::size_t(k)*stride_ + t];
    }

    const double* inData() const { return in_.data(); }
    double* outData() { return out_.data(); }

private:
    int nIn_, nOut_;
    std::size_t n_ = 0, stride_ = 0;
    std::vector<double> in_, out_;
};

} // namespace detail
} // namespace dcprbf
