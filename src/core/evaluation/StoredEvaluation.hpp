// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: an interpolant's values at fixed points (the mesh's
// reference points) as stored weights.
//
// For a set of centres C the kernel matrix K = phi(|x_i - c_j|) at the fixed
// points x_i is stored (compact kernels: sparse, only |x - c| < R, row-major;
// global kernels: dense), with the polynomial basis Q(x). While the centres
// are unchanged, a step costs one product: s(X) = K alpha + Q beta.
//
// Two sets are kept (the current one and the one before: a trial swap that
// is undone, or a blend over the union of two sets, returns to it without a
// rebuild). A set that differs from a stored one in a few centres (a swap,
// a point added) is not rebuilt either: the stored matrix serves the
// centres they share (weight zero for those the set no longer has) and the
// few new centres' columns are computed alone, O(points) each (a patch).
// A set further from the current one, but with at least half of its
// centres in it (a patch outgrown: swaps accumulated), has its matrix
// merged from it (the
// shared columns' entries copied, the new centres' computed) rather than
// built anew. A set whose matrix would exceed the memory budget is not
// stored (prepare() returns false): the caller evaluates on the fly instead.
#pragma once
#include "LinearPolynomial.hpp"
#include "RadialKernel.hpp"
#include <Eigen/SparseCore>
#include <array>
#include <cstdint>
#include <map>
#include <vector>

namespace dcprbf
{

class StoredEvaluation
{
public:
    //- For the fixed points x (rows)
    StoredEvaluation
    (
        const RadialKernel& kernel,
        const LinearPolynomial& polynomial,
        const Points& x
    );

    //- Make the matrix of these centres current: reuse a stored one with the
    //  same centres (same order); else patch a stored one that differs in
    //  at most maxPatchColumns centres either way; else make it into the
    //  other slot: merged from the stored one if that has at least half of
    //  the centres, else built, O(nnz). False (nothing stored) if it would
    //  take more than budget bytes together with the stored one's (with
    //  none current, after a refusal: alone, the stored one dropped).
    bool prepare(const Points& centres, std::size_t budgetBytes);

    //- At most this many new (and this many unused) centres in a patch
    static constexpr int maxPatchColumns = 8;

    //- s(X) = K alpha + Q beta for the current centres (prepare() true)
    void evaluate(const Values& alpha, const Eigen::MatrixX3d& beta, Values& out) const;

    //- Where evaluateInto() writes each row: row i's value to the
    //  3-vectors at out + 3 t for t in point[start[i] .. start[i + 1])
    //  (e.g. a 2D mesh's front and back points of a distinct row). start
    //  has a value per row and one more; a point is the target of one row
    //  at most (rows are written on threads)
    struct Targets
    {
        std::vector<std::size_t> start;
        std::vector<int> point;

        //- Row i's value v to its targets: the first `components` of v,
        //  the others 0
        void write(std::size_t i, const double* v, int components, double* out) const
        {
            for (std::size_t k = start[i]; k < start[i + 1]; ++k)
            {
                double* o = out + 3*std::size_t(point[k]);
                for (int q = 0; q < 3; ++q) o[q] = q < components ? v[q] : 0.0;
            }
        }
    };

    //- evaluate()'s values, bit for bit, written straight to their
    //  targets in out (the first `components` of each, the others 0;
    //  nothing else written): no pass over the rows after the product.
    //  With rows, those rows alone (a trial judged on a few cells: the
    //  same values there, at a fraction of the cost). For a stored sparse
    //  matrix, patched or not; false, nothing written, for a dense one
    bool evaluateInto
    (
        const Values& alpha,
        const Eigen::MatrixX3d& beta,
        const Targets& targets,
        int components,
        double* out,
        const std::vector<int>* rows = nullptr
    ) const;

    //- evaluateInto() at the listed rows for these centres, as if
    //  prepare(centres, budgetBytes) had made them current (the same
    //  values there, bit for bit), without changing what is stored: a set
    //  that a patch of the current slot would serve has its new centres'
    //  kernel values made at those rows alone (a trial swap's mesh at a
    //  few cells: no column over every point). False, nothing written,
    //  for a set prepare() would build, refuse, take from the other slot
    //  or patch from it, whose patch might exceed the budget, or a dense
    //  matrix: where prepare() would change which slot is current (the
    //  sets after it are patched from that one)
    bool evaluateRowsFor
    (
        const Points& centres,
        std::size_t budgetBytes,
        const Values& alpha,
        const Eigen::MatrixX3d& beta,
        const Targets& targets,
        int components,
        double* out,
        const std::vector<int>& rows
    ) const;

    //- Products of fewer kernel entries run on one thread, and a patch
    //  column's kernel values over fewer rows
    static constexpr std::size_t minParallelEntries = std::size_t(1) << 17;
    static constexpr std::ptrdiff_t minParallelRows = 8192;

    //- Bytes held
    std::size_t bytes() const;

    //- Number of matrices made so far (built or merged)
    int builds() const { return builds_; }

    //- Of those, the number merged from a stored one
    int merges() const { return merges_; }

    //- Number of builds tried (refused ones too; a set refused with no
    //  more budget is not tried again)
    int attempts() const { return attempts_; }

    //- Columns computed alone for the current centres (0: no patch)
    int patchColumns() const { return int(patch_.centre.size()); }

private:
    struct Slot
    {
        Points centres;
        // compact kernels: CSR rows (outer), columns (inner8: 8 bits
        // while the centres are at most 256, inner: 16 bits up to 65536,
        // else inner32), values
        std::vector<std::size_t> outer;
        std::vector<std::uint8_t> inner8;
        std::vector<std::uint16_t> inner;
        std::vector<int> inner32;
        std::vector<double> values;
        // global kernels
        Eigen::MatrixXd dense;
        bool used = false;
        std::size_t bytes() const;
    };

    //- A stored matrix serving centres it mostly has
    struct Patch
    {
        Points centres;                 // the centres served
        int base = -1;                  // the slot, -1: no patch
        std::vector<int> column;        // per centre: its slot column or -1
        std::vector<int> centre;        // the centres without one, and
        // their columns by rows (read in the slot's pass over the rows):
        // row i's entries [start[i], start[i + 1]), in the order of
        // centre (entry: the index into centre)
        std::vector<std::uint32_t> start;
        std::vector<std::uint8_t> entry;
        std::vector<double> value;
        std::size_t bytes() const;
        //- The centres without a column, in the order of centre
        Points newCentres() const;
    };

    //- What prepare() does for a set, first: it is the current patch's,
    //  a slot's (slot), refused before with no more room, or to be
    //  patched (from the current slot, else the other) or built
    enum class Step { currentPatch, slot, refused, patchOrBuild };
    struct Plan
    {
        Step step;
        int slot = -1;
    };
    Plan plan(const Points& centres, std::size_t budgetBytes) const;

    //- Bytes held with patch p of nnz entries in place of the current
    //  patch (both slots counted)
    std::size_t patchBytes(const Patch& p, std::size_t nnz) const;

    //- Row x's entries in the new centres cNew, in their order:
    //  emit(e, value) for each within the support; returns their count
    template<class Phi, class Emit>
    static std::uint32_t newEntries
    (
        const Phi& phi, double R2, const double* x, const Points& cNew, Emit emit
    );

    //- Build the matrix of these centres into s; false (s emptied) if it
    //  would take more than budget bytes
    bool build(const Points& centres, std::size_t budget, Slot& s) const;

    //- build()'s matrix of a global kernel: s.dense, sized and filled
    void fillDense(const Points& centres, Slot& s) const;

    //- build()'s matrix of a compact kernel: s's CSR storage counted, then
    //  filled; false (s left empty) if it would take more than budget bytes
    bool buildCompact(const Points& centres, std::size_t budget, Slot& s) const;

    //- Each centre's row in c, by its coordinates (a centre given twice:
    //  its first row)
    static std::map<std::array<double, 3>, int> rowsOf(const Points& c);

    //- Room for a few entries more kept with a compact matrix of n rows
    //  and nnz entries (the next merge's few more do not move it: a
    //  vector's growth would double it, copied), if the budget holds it
    static std::size_t room
    (
        std::size_t n, std::size_t nnz, int indexBytes, std::size_t budget
    );

    //- What merge() did
    enum class Merge { merged, notWorth, tooBig };

    //- Merge the matrix of these centres into s from slot k (a sparse
    //  one): its entries in the centres s shares with it copied (in its
    //  order), those of the others computed after them; notWorth (s
    //  untouched) if fewer than half of the centres are shared, tooBig if
    //  it would take more than budget bytes (so would a build)
    Merge merge(int k, const Points& centres, std::size_t budget, Slot& s) const;

    //- What merge() copies and computes (StoredEvaluationMerge.cpp)
    struct MergePlan;

    //- The plan of a merge from slot k for centres c; false (notWorth) if
    //  the kernel is global, slot k is unused or empty, or fewer than half
    //  of the centres are shared
    bool planMerge(int k, const Points& c, MergePlan& p) const;

    //- merge()'s first pass: row i's number of entries into count[i + 1]
    void countMerged
    (
        const Slot& from, const MergePlan& p, std::vector<std::size_t>& count
    ) const;

    //- s's column and value arrays sized for nnz entries with columns of
    //  indexBytes (room for extra more kept), its dense matrix emptied
    static void sizeStorage(Slot& s, std::size_t nnz, int indexBytes, std::size_t extra);

    //- merge()'s second pass: each row's entries into s (its rows and
    //  storage sized): those copied from slot from, then the new ones
    void fillMerged(const Slot& from, const MergePlan& p, int indexBytes, Slot& s) const;

    //- Patch slot k for these centres; false if they differ too much or
    //  it would take more than budget bytes
    bool patch(int k, const Points& centres, std::size_t budget);

    //- The plan of a patch of slot k for centres c: p's centres, base,
    //  column and centre (no entries); false if they differ in more than
    //  maxPatchColumns centres either way
    bool planPatch(int k, const Points& c, Patch& p) const;

    //- A patch's entry for point i and centre c: within the support (or
    //  a global kernel), and the kernel's value there (0 outside)
    template<class Phi>
    static bool entry(const Phi& phi, double R2, const double* x, const double* c, double& value);

    //- The patched set's weights alpha in slot s's columns
    Values slotWeights(const Slot& s, const Patch& patch, const Values& alpha) const;


    //- Throw unless targets has a start per row (and one more) and the
    //  rows (if any) are rows of the matrix
    void checkTargets(const Targets& targets, const std::vector<int>* rows) const;

    //- Where a product's rows go instead of out (evaluateInto)
    struct Scatter
    {
        const Targets& targets;
        int components;
        double* out;
    };

    //- out = K alpha + Q beta for slot s, the first C columns (the others
    //  zero); out sized. With a scatter, the rows to its targets instead
    //  (a sparse slot). With the patch's weights (C per patch column),
    //  each row's entries of patch added after Q beta (byPosition: its
    //  entries are by position in rows, not by row). With rows (and a
    //  scatter), only those rows
    template<int C>
    void product
    (
        const Slot& s,
        const Values& alpha,
        const Eigen::MatrixX3d& beta,
        Values& out,
        const Scatter* scatter,
        const double* patchWeights,
        const std::vector<int>* rows,
        const Patch& patch,
        bool byPosition
    ) const;

    //- The product of slot s (patched: with the patch's columns, in the
    //  same pass over the rows) into out or to the scatter's targets
    void productOf
    (
        const Slot& s,
        const Values& alpha,
        const Eigen::MatrixX3d& beta,
        Values& out,
        const Scatter* scatter = nullptr,
        const std::vector<int>* rows = nullptr
    ) const;

    //- The same with this patch (not the current one)
    void productOf
    (
        const Slot& s,
        const Patch& patch,
        bool byPosition,
        const Values& alpha,
        const Eigen::MatrixX3d& beta,
        Values& out,
        const Scatter* scatter,
        const std::vector<int>* rows
    ) const;

    RadialKernel kernel_;
    LinearPolynomial polynomial_;
    Points x_;
    // Q(x) without its first column (the ones): points x (polynomial size
    // - 1), row-major (read with each row of K)
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> basis_;
    std::array<Slot, 2> slots_;
    int current_ = -1;
    Patch patch_;
    int builds_ = 0;
    int merges_ = 0;
    int attempts_ = 0;
    Points refused_;                // the last set refused, and its budget
    std::size_t refusedBudget_ = 0;
};

template<class Phi>
inline bool StoredEvaluation::entry
(
    const Phi& phi,
    const double R2,
    const double* x,
    const double* c,
    double& value
)
{
    const double d0 = x[0] - c[0], d1 = x[1] - c[1], d2 = x[2] - c[2];
    const double r2 = d0*d0 + d1*d1 + d2*d2;
    const bool within = R2 < 0 || r2 < R2;
    value = within ? phi.ofSquared(r2) : 0.0;
    return within;
}

template<class Phi, class Emit>
inline std::uint32_t StoredEvaluation::newEntries
(
    const Phi& phi,
    const double R2,
    const double* x,
    const Points& cNew,
    Emit emit
)
{
    std::uint32_t m = 0;
    double v;
    for (Eigen::Index e = 0; e < cNew.rows(); ++e)
    {
        if (entry(phi, R2, x, &cNew(e, 0), v))
        {
            emit(std::size_t(e), v);
            ++m;
        }
    }
    return m;
}

} // namespace dcprbf
