#include "stability/mode_kind.hpp"

#include <Eigen/LU>

#include <cmath>
#include <complex>

namespace sphkern {

std::string mode_kind_name(ModeKind kind)
{
    switch (kind) {
    case ModeKind::longitudinal: return "longitudinal";
    case ModeKind::transverse: return "transverse";
    case ModeKind::optical: return "optical";
    }
    return "transverse";
}

namespace {

// Whether the translation from site 0 to each site maps the structure onto itself: the cell
// is then a supercell of a Bravais lattice (bcc as a cubic cell) and its branches are folded
// acoustic ones; otherwise (hcp) the sites are sublattices that can move against each other.
bool bravais_supercell(const Dispersion& d)
{
    const Eigen::Matrix3d to_cells = d.basis().inverse();
    auto same_site = [&](const Eigen::Vector3d& x, int v) {
        const Eigen::Vector3d cells = to_cells * (x - d.site_offset(v));
        return (cells - cells.array().round().matrix()).norm() < 1e-9;
    };
    for (int s = 1; s < d.sites(); ++s)
        for (int u = 0; u < d.sites(); ++u) {
            bool lands = false;
            for (int v = 0; v < d.sites() && !lands; ++v) lands = same_site(d.site_offset(u) + d.site_offset(s), v);
            if (!lands) return false;
        }
    return true;
}

} // namespace

ModeCharacter mode_character(const Dispersion& dispersion, const ReciprocalLattice& reciprocal,
                             const Eigen::Vector3d& kappa, int branch)
{
    const int D = dispersion.dimension(), n = dispersion.sites();
    const Eigen::VectorXcd xi = dispersion.modes(kappa).modes[static_cast<std::size_t>(branch)];
    // The in-phase motion for a reciprocal vector G: v = sum_s xi_s exp(-i G.x_s).
    auto in_phase = [&](const Eigen::Vector3d& G) {
        Eigen::Vector3cd v = Eigen::Vector3cd::Zero();
        for (int s = 0; s < n; ++s) {
            const std::complex<double> phase = std::polar(1.0, -G.dot(dispersion.site_offset(s)));
            for (int a = 0; a < D; ++a) v[a] += phase * xi[D * s + a];
        }
        return v;
    };
    ModeCharacter best;
    best.in_phase = -1;
    Eigen::Vector3cd motion = Eigen::Vector3cd::Zero();
    // One site: every G gives the same motion, keep kappa; sublattices: no unfolding.
    const int reach = n > 1 && bravais_supercell(dispersion) ? 1 : 0;
    for (int i = -reach; i <= reach; ++i)
        for (int j = (D > 1 ? -reach : 0); j <= (D > 1 ? reach : 0); ++j)
            for (int l = (D > 2 ? -reach : 0); l <= (D > 2 ? reach : 0); ++l) {
                const Eigen::Vector3d G = reciprocal.vectors * Eigen::Vector3d(i, j, l);
                const Eigen::Vector3cd v = in_phase(G);
                const double together = v.squaredNorm() / (n * xi.squaredNorm());
                const Eigen::Vector3d q = kappa + G;
                const bool better = together > best.in_phase + 1e-9 ||
                                    (together > best.in_phase - 1e-9 && q.norm() < best.unfolded.norm());
                if (better) best.in_phase = together, best.unfolded = q, motion = v;
            }
    const double length = best.unfolded.head(D).norm();
    if (length > 0 && motion.squaredNorm() > 0) {
        std::complex<double> along = 0;
        for (int a = 0; a < D; ++a) along += best.unfolded[a] / length * motion[a];
        best.longitudinal = std::norm(along) / motion.squaredNorm();
    }
    best.kind = best.in_phase < 0.5       ? ModeKind::optical
                : best.longitudinal > 0.5 ? ModeKind::longitudinal
                                          : ModeKind::transverse;
    return best;
}

} // namespace sphkern
