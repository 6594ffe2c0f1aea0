// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: quality of a deformed tetrahedron relative to its
// reference shape (Knupp-style size-shape metric with the reference element
// as target).
//
// With E0 and E the edge matrices (columns p1-p0, p2-p0, p3-p0) of the
// reference and the deformed tetrahedron, A = E E0^-1 is the deformation
// gradient and J = det A = V/V0. Then
//
//     f_size  = min(J, 1/J)
//     f_shape = 3 J^(2/3) / |A|_F^2          (1 iff A is a scaled rotation)
//     q       = sqrt(f_size) f_shape          for J > 0
//     q       = J                             for J <= 0 (inverted, degenerate)
//
// so q = 1 for a rigid motion of the tetrahedron, 0 < q < 1 for a distorted
// one, q <= 0 for an inverted or flat one. A degenerate reference (V0 = 0)
// gives q = 1 (nothing to compare with). Metric::size keeps only f_size,
// Metric::shape only f_shape (both with q = J for J <= 0).
#pragma once

#include <Eigen/Core>

namespace dcprbf
{

class TetQuality
{
public:
    enum class Metric { sizeShape, size, shape };

    //- Quality of the tetrahedron (p0, p1, p2, p3) moved to (q0, q1, q2, q3)
    static double compute
    (
        const Eigen::Vector3d ref[4],
        const Eigen::Vector3d cur[4],
        Metric metric = Metric::sizeShape
    );

    //- Quality from the edge matrices (columns: edges from vertex 0)
    static double compute
    (
        const Eigen::Matrix3d& E0,
        const Eigen::Matrix3d& E,
        Metric metric = Metric::sizeShape
    );
};

} // namespace dcprbf
