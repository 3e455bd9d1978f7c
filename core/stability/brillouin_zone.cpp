#include "stability/brillouin_zone.hpp"

#include "lattices/lattice_points.hpp"

#include <Eigen/LU>

#include <array>
#include <cmath>

namespace sphkern {

namespace {

constexpr double two_pi = 6.283185307179586476925286766559;

bool near(double a, double b) { return std::abs(a - b) < 1e-9; }

// A primitive basis of the lattice made of its shortest vectors (and, for `hexagonal`, the
// shortest vector normal to two of them at 120 degrees) whose pairwise cosines are `cosine`.
bool find_basis(const Eigen::Matrix3d& reduced, int dim, double cosine, bool hexagonal, Eigen::Matrix3d& found)
{
    const double volume = std::abs(dim == 3 ? reduced.determinant() : reduced.topLeftCorner(2, 2).determinant());
    std::vector<Eigen::Vector3d> vectors;
    for (int i = -2; i <= 2; ++i)
        for (int j = (dim > 1 ? -2 : 0); j <= (dim > 1 ? 2 : 0); ++j)
            for (int l = (dim > 2 ? -2 : 0); l <= (dim > 2 ? 2 : 0); ++l)
                if (i || j || l) vectors.push_back(reduced * Eigen::Vector3d(i, j, l));
    double shortest = INFINITY;
    for (const auto& v : vectors) shortest = std::min(shortest, v.norm());
    std::vector<Eigen::Vector3d> first;
    for (const auto& v : vectors)
        if (near(v.norm() / shortest, 1)) first.push_back(v);
    auto cos_of = [](const Eigen::Vector3d& u, const Eigen::Vector3d& v) { return u.dot(v) / (u.norm() * v.norm()); };
    for (const auto& u : first)
        for (const auto& v : first) {
            if (!near(cos_of(u, v), hexagonal ? -0.5 : cosine)) continue;
            if (dim == 2) {
                if (!near(std::abs(u.x() * v.y() - u.y() * v.x()) / volume, 1)) continue;
                found.col(0) = u, found.col(1) = v, found.col(2) = Eigen::Vector3d::UnitZ();
                return true;
            }
            const auto& third_set = hexagonal ? vectors : first;
            double best = INFINITY;
            for (const auto& w : third_set) {
                const bool angles = hexagonal ? near(cos_of(u, w), 0) && near(cos_of(v, w), 0)
                                              : near(cos_of(u, w), cosine) && near(cos_of(v, w), cosine);
                if (!angles || w.norm() >= best) continue;
                Eigen::Matrix3d t;
                t << u, v, w;
                if (!near(std::abs(t.determinant()) / volume, 1)) continue;
                best = w.norm();
                found = t;
            }
            if (best < INFINITY) return true;
        }
    return false;
}

// The reciprocal vectors of D columns of `a`.
Eigen::Matrix3d reciprocal_of(const Eigen::Matrix3d& a, int dim)
{
    Eigen::Matrix3d full = a;
    if (dim == 2) full.col(2) = Eigen::Vector3d::UnitZ();
    if (dim == 1) full.col(1) = Eigen::Vector3d::UnitY(), full.col(2) = Eigen::Vector3d::UnitZ();
    return two_pi * full.inverse().transpose();
}

} // namespace

ReciprocalLattice reciprocal_lattice(const Lattice& lattice)
{
    const int D = lattice.dimension;
    const Eigen::Matrix3d reduced = reduce_basis(lattice.basis, D).first;
    ReciprocalLattice r;
    r.dimension = D;
    r.bravais = "general";
    Eigen::Matrix3d a = reduced;
    struct Kind {
        int dim;
        const char* name;
        double cosine;
        bool hexagonal;
    };
    static const std::array<Kind, 6> kinds{{{2, "square", 0.0, false},
                                            {2, "triangular", -0.5, false},
                                            {3, "sc", 0.0, false},
                                            {3, "fcc", 0.5, false},
                                            {3, "bcc", -1.0 / 3, false},
                                            {3, "hexagonal", 0.0, true}}};
    for (const auto& kind : kinds)
        if (kind.dim == D && find_basis(reduced, D, kind.cosine, kind.hexagonal, a)) {
            r.bravais = kind.name;
            break;
        }
    r.vectors = reciprocal_of(a, D);
    return r;
}

Eigen::Vector3d fold_to_first_zone(const ReciprocalLattice& reciprocal, const Eigen::Vector3d& kappa)
{
    const int D = reciprocal.dimension;
    const Eigen::Matrix3d b = reduce_basis(reciprocal.vectors, D).first;
    // Reduce to the parallelepiped around 0, then try the neighbouring images.
    Eigen::Vector3d f = b.inverse() * kappa;
    for (int i = 0; i < D; ++i) f[i] -= std::round(f[i]);
    Eigen::Vector3d base = b * f;
    if (D < 3) base[2] = kappa[2], base.tail(3 - D).setZero();
    Eigen::Vector3d best = base;
    const int m = 2;
    for (int i = -m; i <= m; ++i)
        for (int j = (D > 1 ? -m : 0); j <= (D > 1 ? m : 0); ++j)
            for (int l = (D > 2 ? -m : 0); l <= (D > 2 ? m : 0); ++l) {
                Eigen::Vector3d c = base + b * Eigen::Vector3d(i, j, l);
                if (c.norm() < best.norm() - 1e-12) best = c;
            }
    return best;
}

std::vector<SymmetryPoint> high_symmetry_path(const ReciprocalLattice& r)
{
    const Eigen::Matrix3d& b = r.vectors;
    const Eigen::Vector3d G = Eigen::Vector3d::Zero();
    const std::string gamma = "Γ";
    if (r.bravais == "sc") {
        const Eigen::Vector3d X = b.col(0) / 2, M = (b.col(0) + b.col(1)) / 2, R = (b.col(0) + b.col(1) + b.col(2)) / 2;
        return {{gamma, G}, {"X", X}, {"M", M}, {gamma, G}, {"R", R}};
    }
    if (r.bravais == "fcc") {
        // With all direct angles at 60 degrees, the cube edge directions are b_i + b_j.
        const Eigen::Vector3d x = (b.col(1) + b.col(2)) / 2, y = (b.col(0) + b.col(2)) / 2,
                              z = (b.col(0) + b.col(1)) / 2;
        // x, y, z are 2 pi / a times the conventional unit vectors: X, W, L, K as usual.
        const Eigen::Vector3d X = x, W = x + 0.5 * y, L = 0.5 * (x + y + z), K = 0.75 * (x + y);
        return {{gamma, G}, {"X", X}, {"W", W}, {"L", L}, {gamma, G}, {"K", K}};
    }
    if (r.bravais == "bcc") {
        // Direct angles with cosine -1/3: b_j + b_l - b_i is twice 2 pi / a along a cube edge.
        const Eigen::Vector3d x = (b.col(1) + b.col(2) - b.col(0)) / 2, y = (b.col(0) + b.col(2) - b.col(1)) / 2,
                              z = (b.col(0) + b.col(1) - b.col(2)) / 2;
        const Eigen::Vector3d H = z, N = 0.5 * (x + z), P = 0.5 * (x + y + z);
        return {{gamma, G}, {"H", H}, {"N", N}, {gamma, G}, {"P", P}};
    }
    if (r.bravais == "hexagonal" || r.bravais == "triangular") {
        // Direct in-plane vectors at 120 degrees: b1, b2 at 60 degrees, K = (b1 + b2) / 3.
        const Eigen::Vector3d M = b.col(0) / 2, K = (b.col(0) + b.col(1)) / 3;
        if (r.bravais == "triangular") return {{gamma, G}, {"M", M}, {"K", K}, {gamma, G}};
        const Eigen::Vector3d A = b.col(2) / 2;
        return {{gamma, G}, {"M", M}, {"K", K}, {gamma, G}, {"A", A}, {"L", M + A}, {"H", K + A}, {"A", A}};
    }
    if (r.bravais == "square") {
        const Eigen::Vector3d X = b.col(0) / 2, M = (b.col(0) + b.col(1)) / 2;
        return {{gamma, G}, {"X", X}, {"M", M}, {gamma, G}};
    }
    std::vector<SymmetryPoint> path{{gamma, G}};
    Eigen::Vector3d corner = Eigen::Vector3d::Zero();
    for (int i = 0; i < r.dimension; ++i) {
        corner += b.col(i) / 2;
        path.push_back({"B" + std::to_string(i + 1) + "/2" + (i ? " sum" : ""), corner});
    }
    path.push_back({gamma, G});
    return path;
}

} // namespace sphkern
