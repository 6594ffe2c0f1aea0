// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "PlanarPolygonBatch.hpp"

#include "TetKernel.hpp"
#include "LaneWorst.hpp"
#include "TetMeasures.hpp"

#include <algorithm>
#include <type_traits>

namespace dcprbf
{
namespace detail
{

namespace
{

//- Cells per chunk: a chunk's lanes stay in the L1 cache
constexpr std::size_t chunkSize = 128;

//- Map j of nMaps: current edges fa, fb; its reference (inverse, flag)
//  from r, components ss apart; J and |A|^2 into o (so apart)
template<int M, int nMaps>
DCPRBF_ALWAYS_INLINE void addMap
(
    LaneWorst& w,
    const int j,
    const double fa0, const double fa1,
    const double fb0, const double fb1,
    const double* __restrict r,
    const std::size_t ss,
    double* __restrict o,
    const std::size_t so
)
{
    // PlanarMapBatch's operations
    const double i00 = r[(4*j)*ss], i01 = r[(4*j + 1)*ss];
    const double i10 = r[(4*j + 2)*ss], i11 = r[(4*j + 3)*ss];
    const double f00 = fa0*i00 + fb0*i10, f01 = fa0*i01 + fb0*i11;
    const double f10 = fa1*i00 + fb1*i10, f11 = fa1*i01 + fb1*i11;
    const double Jf = f00*f11 - f01*f10;
    const double a2f = f00*f00 + f01*f01 + f10*f10 + f11*f11 + 1;
    const bool degenerate = r[(4*nMaps + j)*ss] > 0;
    const double J = degenerate ? -1.0 : Jf;
    const double a2 = degenerate ? -1.0 : a2f;
    const double k = tetKernel::key<M>(J, a2);
    o[(2 + 2*j)*so] = J;
    o[(3 + 2*j)*so] = a2;

    w.add(J, a2, k);
}


//- A triangle's map (its own: edges from point 0) into w; the current
//  points from p, components sx apart; the references from r (ss apart);
//  J and |A|^2 into o (sx apart)
template<int M>
DCPRBF_ALWAYS_INLINE void addMaps
(
    std::integral_constant<int, 3>,
    LaneWorst& w,
    const double* __restrict p,
    const std::size_t sx,
    const double* __restrict r,
    const std::size_t ss,
    double* __restrict o
)
{
    const double x0 = p[0], y0 = p[sx], x1 = p[2*sx], y1 = p[3*sx];
    const double x2 = p[4*sx], y2 = p[5*sx];
    addMap<M, 1>(w, 0, x1 - x0, y1 - y0, x2 - x0, y2 - y0, r, ss, o, sx);
}


//- A quadrilateral's four maps (the vertex average, the edge from point j)
template<int M>
DCPRBF_ALWAYS_INLINE void addMaps
(
    std::integral_constant<int, 4>,
    LaneWorst& w,
    const double* __restrict p,
    const std::size_t sx,
    const double* __restrict r,
    const std::size_t ss,
    double* __restrict o
)
{
    const double x0 = p[0], y0 = p[sx], x1 = p[2*sx], y1 = p[3*sx];
    const double x2 = p[4*sx], y2 = p[5*sx], x3 = p[6*sx], y3 = p[7*sx];
    // the vertex average as PlanarCellQualityScan sums it
    const double cx = (((0.0 + x0) + x1) + x2) + x3;
    const double cy = (((0.0 + y0) + y1) + y2) + y3;
    const double c0 = cx/4.0, c1 = cy/4.0;
    // the points from the vertex average
    const double u0 = x0 - c0, v0 = y0 - c1, u1 = x1 - c0, v1 = y1 - c1;
    const double u2 = x2 - c0, v2 = y2 - c1, u3 = x3 - c0, v3 = y3 - c1;
    addMap<M, 4>(w, 0, u0, v0, u1, v1, r, ss, o, sx);
    addMap<M, 4>(w, 1, u1, v1, u2, v2, r, ss, o, sx);
    addMap<M, 4>(w, 2, u2, v2, u3, v3, r, ss, o, sx);
    addMap<M, 4>(w, 3, u3, v3, u0, v0, r, ss, o, sx);
}


//- In: the N current points (x y each), components sx apart; the
//  references r, ss apart; out (sx apart): the quality, the number of maps
//  beyond the key's range, J and |A|^2 of each map
template<int N>
struct Kernel
{
template<int M>
static DCPRBF_ALWAYS_INLINE void run
(
    const std::size_t n,
    const double* __restrict x,
    const std::size_t sx,
    const double* __restrict r,
    const std::size_t ss,
    double* __restrict out
)
{
    #pragma omp simd
    for (std::size_t t = 0; t < n; ++t)
    {
        LaneWorst w;
        addMaps<M>(std::integral_constant<int, N>(), w, x + t, sx, r + t, ss, out + t);
        out[t] = w.quality<M>();
        out[sx + t] = w.beyond;
    }
}
};

} // namespace


template<int N>
void PlanarPolygonBatch<N>::add
(
    const std::size_t cell,
    const int points[N],
    const double inverse[4*nMaps],
    const bool degenerate[nMaps]
)
{
    cells_.push_back(cell);
    points_.insert(points_.end(), points, points + N);
    reference_.insert(reference_.end(), inverse, inverse + 4*nMaps);
    for (int j = 0; j < nMaps; ++j) reference_.push_back(degenerate[j] ? 1.0 : 0.0);
}


template<int N>
void PlanarPolygonBatch<N>::finishAdding()
{
    const std::size_t n = size(), nc = 5*nMaps;
    stride_ = n;
    std::vector<double> lanes(nc*n);
    for (std::size_t t = 0; t < n; ++t)
    {
        for (std::size_t k = 0; k < nc; ++k) lanes[k*n + t] = reference_[nc*t + k];
    }
    reference_.swap(lanes);
}


template<int N>
void PlanarPolygonBatch<N>::measureChunk
(
    const std::size_t t0,
    const std::size_t t1,
    const double* x,
    double* q,
    const TetQuality::Metric metric,
    LaneArrays& s,
    WorstBatch& finals
) const
{
    const std::size_t n = t1 - t0;
    s.resize(n);
    for (std::size_t t = 0; t < n; ++t)
    {
        const int* v = &points_[N*(t0 + t)];
        for (int k = 0; k < N; ++k)
        {
            s.in(2*k, t) = x[2*std::size_t(v[k])];
            s.in(2*k + 1, t) = x[2*std::size_t(v[k]) + 1];
        }
    }
    tetKernel::dispatch<Kernel<N>>
    (
        metric, finals.wide(), n, s.inData(), s.stride(), reference_.data() + t0, stride_,
        s.outData()
    );
    for (std::size_t t = 0; t < n; ++t)
    {
        if (s.out(1, t) == 0)
        {
            q[cells_[t0 + t]] = s.out(0, t);
            continue;
        }
        TetMeasures::Worst worst(metric);
        for (int j = 0; j < nMaps; ++j) worst.add(s.out(2 + 2*j, t), s.out(3 + 2*j, t));
        finals.add(worst, q + cells_[t0 + t]);
    }
    finals.finish();
}


template<int N>
void PlanarPolygonBatch<N>::measure
(
    const double* x,
    double* q,
    const TetQuality::Metric metric,
    const bool wide
) const
{
    LaneArrays s(2*N, 2 + 2*nMaps);
    WorstBatch finals(metric, wide);
    const long nChunks = long((size() + chunkSize - 1)/chunkSize);
    #pragma omp for schedule(static)
    for (long c = 0; c < nChunks; ++c)
    {
        const std::size_t t0 = std::size_t(c)*chunkSize;
        measureChunk(t0, std::min(size(), t0 + chunkSize), x, q, metric, s, finals);
    }
}


template class PlanarPolygonBatch<3>;
template class PlanarPolygonBatch<4>;

} // namespace detail
} // namespace dcprbf
