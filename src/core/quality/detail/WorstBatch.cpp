// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "WorstBatch.hpp"
#include "TetBatch.hpp"

namespace dcprbf
{
namespace detail
{

void WorstBatch::finish()
{
    q_.resize(J_.size());
    TetBatch::qualities(J_.size(), J_.data(), a2_.data(), q_.data(), metric_, wide_);
    for (std::size_t i = 0; i < q_.size(); ++i)
    {
        *dest_[i] = q_[i] < other_[i] ? q_[i] : other_[i];
    }
    J_.clear();
    a2_.clear();
    other_.clear();
    dest_.clear();
}

} // namespace detail
} // namespace dcprbf
