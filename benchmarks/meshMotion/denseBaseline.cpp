// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Mesh-motion benchmark baseline: the precomputed dense kernel matrix.
//
//   denseBaseline points.txt centres.txt dim radius repeats [nResample]
//
// points.txt, centres.txt: "n" then n lines "x y z" (2D: the plane z is
// ignored). Builds the dense (points x centres) WendlandC2 matrix K once and
// the polynomial basis Q, then times s = K alpha + Q beta (3 right-hand
// sides, random alpha, beta) over `repeats` products, with K stored by
// columns (Eigen's product) and by rows (each row's three sums in one stream
// over K, blocks of rows on the threads; also cold: each product after a
// pass over 256 MB); the same with the
// core's StoredEvaluation (sparse CSR for the compact kernel) on the same
// data. nResample > 0: the points are first resampled to nResample points
// (each a random mesh point + a 1e-4 radius jitter: the same distribution as
// the mesh, n times denser). Also the stored product patched with 3 and 6
// columns computed alone (a dynamic set after swaps). Prints key value lines.
#include "LinearPolynomial.hpp"
#include "RadialKernel.hpp"
#include "StoredEvaluation.hpp"
#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <vector>

using namespace dcprbf;

static Points readPoints(const std::string& file, int dim)
{
    std::ifstream f(file);
    long n = 0;
    if (!(f >> n)) throw std::runtime_error("cannot read " + file);
    Points p(n, 3);
    for (long i = 0; i < n; ++i)
    {
        f >> p(i, 0) >> p(i, 1) >> p(i, 2);
        if (dim == 2) p(i, 2) = 0;
    }
    if (!f) throw std::runtime_error("short file " + file);
    return p;
}

static double now()
{
    return std::chrono::duration<double>(
        std::chrono::steady_clock::now().time_since_epoch()).count();
}

static double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size()/2];
}

int main(int argc, char** argv)
{
    if (argc < 6)
    {
        std::cerr << "usage: denseBaseline points centres dim radius repeats [nResample]\n";
        return 2;
    }
    const int dim = std::stoi(argv[3]);
    const double R = std::stod(argv[4]);
    const int repeats = std::stoi(argv[5]);
    const long nResample = argc > 6 ? std::stol(argv[6]) : 0;
    Points x = readPoints(argv[1], dim);
    const Points c = readPoints(argv[2], dim);
    std::mt19937_64 rng(12345);
    if (nResample > 0)
    {
        std::uniform_int_distribution<long> pick(0, x.rows() - 1);
        std::normal_distribution<double> jitter(0.0, 1e-4);
        Points y(nResample, 3);
        for (long i = 0; i < nResample; ++i)
        {
            y.row(i) = x.row(pick(rng));
            for (int k = 0; k < dim; ++k) y(i, k) += jitter(rng);
        }
        x.swap(y);
    }
    const long n = x.rows(), N = c.rows();
    const RadialKernel kernel(RadialKernel::Type::WendlandC2, R);
    const LinearPolynomial poly = LinearPolynomial::boundingBox(true, dim, c);

    Values alpha(N, 3);
    std::uniform_real_distribution<double> u(-1, 1);
    for (long j = 0; j < N; ++j) for (int k = 0; k < 3; ++k) alpha(j, k) = u(rng);
    Eigen::MatrixX3d beta(poly.size(), 3);
    for (int j = 0; j < poly.size(); ++j) for (int k = 0; k < 3; ++k) beta(j, k) = u(rng);

    // dense: K (column-major, n x N) and Q (n x (dim+1)), built once
    double t0 = now();
    Eigen::MatrixXd K(n, N);
    #pragma omp parallel for schedule(static)
    for (long j = 0; j < N; ++j)
    {
        for (long i = 0; i < n; ++i)
        {
            K(i, j) = kernel((x.row(i) - c.row(j)).norm());
        }
    }
    const Eigen::MatrixXd Q = poly.basis(x);
    const double denseBuild = now() - t0;
    long nnz = 0;
    for (long j = 0; j < N; ++j) for (long i = 0; i < n; ++i) nnz += K(i, j) != 0;

    Eigen::MatrixX3d alphaC = alpha;    // column-major right-hand sides
    Eigen::MatrixX3d sDense(n, 3);
    std::vector<double> tDense, tSparse;
    for (int r = 0; r < repeats; ++r)
    {
        const double t = now();
        sDense.noalias() = K*alphaC;
        sDense.noalias() += Q*beta;
        tDense.push_back(now() - t);
    }

    // the same dense matrix stored by rows: one stream over K, each row's
    // three sums while it is in cache (a mover that keeps its matrix by rows)
    // Timed warm (one product after the other, as the others) and cold:
    // after a pass over a buffer larger than the caches, as in a run, where
    // the solver's work of the step comes between two products
    std::vector<double> tDenseRows, tDenseRowsCold;
    Eigen::MatrixX3d sRows(n, 3);
    {
        const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> KR(K);
        const auto product = [&]()
        {
            const double t = now();
            // blocks of rows on the threads (OMP_NUM_THREADS, as the others)
            constexpr long block = 4096;
            #pragma omp parallel for schedule(static)
            for (long i0 = 0; i0 < n; i0 += block)
            {
                const long m = std::min(block, n - i0);
                sRows.middleRows(i0, m).noalias() = KR.middleRows(i0, m).lazyProduct(alphaC);
            }
            sRows.noalias() += Q*beta;
            return now() - t;
        };
        std::vector<double> flush(std::size_t(32) << 20);    // 256 MB
        double sink = 0;
        for (int r = 0; r < repeats; ++r)
        {
            tDenseRows.push_back(product());
        }
        for (int r = 0; r < repeats; ++r)
        {
            for (double& f : flush) f += 1;
            sink += flush[std::size_t(r)];
            tDenseRowsCold.push_back(product());
        }
        if (sink < 0) std::printf("%g\n", sink);
    }

    // the core's stored (sparse) evaluation
    StoredEvaluation stored(kernel, poly, x);
    t0 = now();
    if (!stored.prepare(c, std::size_t(1) << 40))
    {
        std::cerr << "StoredEvaluation refused the matrix\n";
        return 1;
    }
    const double sparseBuild = now() - t0;
    const std::size_t sparseBytes = stored.bytes();     // before any patch
    Values sSparse(n, 3);
    for (int r = 0; r < repeats; ++r)
    {
        const double t = now();
        stored.evaluate(alpha, beta, sSparse);
        tSparse.push_back(now() - t);
    }
    const double diff = (sDense - Eigen::MatrixX3d(sSparse)).cwiseAbs().maxCoeff()
        /std::max(1e-300, sDense.cwiseAbs().maxCoeff());

    // the same matrix patched (a dynamic set after swaps): the last k
    // centres moved by R/100, their columns computed alone
    std::vector<std::pair<int, double>> tPatched;
    for (const int k : {3, 6})
    {
        if (k >= N) continue;
        Points cp = c;
        for (long j = N - k; j < N; ++j) cp(j, 0) += 0.01*R;
        if (!stored.prepare(cp, std::size_t(1) << 40) || stored.patchColumns() != k)
        {
            std::cerr << "StoredEvaluation did not patch " << k << " columns\n";
            return 1;
        }
        std::vector<double> t;
        for (int r = 0; r < repeats; ++r)
        {
            const double t1 = now();
            stored.evaluate(alpha, beta, sSparse);
            t.push_back(now() - t1);
        }
        tPatched.emplace_back(k, median(t));
    }

    std::printf("points %ld\ncentres %ld\nnnzFraction %.4f\n", n, N, double(nnz)/(double(n)*N));
    std::printf("denseBytes %.0f\ndenseBuild %.6f\ndenseProduct %.6e\n",
        double(K.size() + Q.size())*sizeof(double), denseBuild, median(tDense));
    std::printf("sparseBytes %.0f\nsparseBuild %.6f\nsparseProduct %.6e\n",
        double(sparseBytes + Q.size()*sizeof(double)), sparseBuild, median(tSparse));
    for (const auto& kt : tPatched)
    {
        std::printf("sparsePatched%dProduct %.6e\n", kt.first, kt.second);
    }
    std::printf("denseRowsProduct %.6e\n", median(tDenseRows));
    std::printf("denseRowsColdProduct %.6e\n", median(tDenseRowsCold));
    std::printf("maxRelDiff %.2e\n", diff);
    std::printf("maxRelDiffRows %.2e\n", (sDense - sRows).cwiseAbs().maxCoeff()
        /std::max(1e-300, sDense.cwiseAbs().maxCoeff()));
    return 0;
}
