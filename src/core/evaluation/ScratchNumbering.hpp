// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: items numbered in order of first use through a
// scratch array its owner keeps between uses (-1 where unnumbered): a
// subset's renumbering costs its own items, not a pass over all of them.
#pragma once

#include <cstddef>
#include <vector>

namespace dcprbf
{

class ScratchNumbering
{
public:
    //- Over items 0 .. n-1, with the owner's scratch (sized here)
    ScratchNumbering(std::vector<int>& scratch, std::size_t n)
    :
        scratch_(scratch)
    {
        scratch_.resize(n, -1);
    }

    ScratchNumbering(const ScratchNumbering&) = delete;
    ScratchNumbering& operator=(const ScratchNumbering&) = delete;

    //- The scratch back to -1 where it was set
    ~ScratchNumbering()
    {
        for (const int i : numbered_) scratch_[std::size_t(i)] = -1;
    }

    //- Item i's number; onNew(i) called when it is numbered (first use)
    template<class OnNew>
    int operator()(int i, OnNew onNew)
    {
        int& k = scratch_[std::size_t(i)];
        if (k < 0)
        {
            // (listed first: reset even if what follows throws)
            numbered_.push_back(i);
            k = int(numbered_.size()) - 1;
            onNew(i);
        }
        return k;
    }

private:
    std::vector<int>& scratch_;
    std::vector<int> numbered_;
};

} // namespace dcprbf
