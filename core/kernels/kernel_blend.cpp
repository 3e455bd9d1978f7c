#include "kernels/kernel_blend.hpp"

#include "support/error.hpp"

#include <algorithm>
#include <vector>

namespace sphkern {

namespace {

class BlendFunctions final : public KernelFunctions {
public:
    BlendFunctions(Kernel a, Kernel b) : a_(std::move(a)), b_(std::move(b)) {}

    double w(double q, int dim, double k, const double* p) const override
    {
        return (1 - p[0]) * a_.w_truncated(q, dim, k) + p[0] * b_.w_truncated(q, dim, k);
    }
    double dw(double q, int dim, double k, const double* p) const override
    {
        return (1 - p[0]) * a_.dw_truncated(q, dim, k) + p[0] * b_.dw_truncated(q, dim, k);
    }
    void w_batch(const double* q, double* out, std::size_t n, int dim, double k, const double* p) const override
    {
        combine(q, out, n, p[0], [&](const Kernel& x, const double* qs, double* o) { x.w_batch(qs, o, n, dim, k); });
    }
    void dw_batch(const double* q, double* out, std::size_t n, int dim, double k, const double* p) const override
    {
        combine(q, out, n, p[0], [&](const Kernel& x, const double* qs, double* o) { x.dw_batch(qs, o, n, dim, k); });
    }

private:
    template <class Batch>
    void combine(const double* q, double* out, std::size_t n, double alpha, const Batch& batch) const
    {
        thread_local std::vector<double> other;
        other.resize(n);
        batch(a_, q, out);
        batch(b_, q, other.data());
        const double ra = a_.support(), rb = b_.support();
        for (std::size_t i = 0; i < n; ++i)
            out[i] = (1 - alpha) * (q[i] > ra ? 0.0 : out[i]) + alpha * (q[i] > rb ? 0.0 : other[i]);
    }

    Kernel a_, b_;
};

} // namespace

std::shared_ptr<const KernelDefinition> make_blend(const Kernel& a, const Kernel& b)
{
    const auto &da = a.definition(), &db = b.definition();
    auto blend = std::make_shared<KernelDefinition>();
    blend->name = da.name + "+" + db.name;
    blend->title = "(1 - alpha) " + da.name + " + alpha " + db.name;
    blend->reference = "blend of: " + da.reference + " | " + db.reference;
    blend->source = "blend of " + da.source + " and " + db.source;
    blend->support = std::max(da.support, db.support);
    for (int d : da.dimensions)
        if (db.supports(d)) blend->dimensions.push_back(d);
    if (blend->dimensions.empty())
        fail_input("kernels " + da.name + " (" + da.dimensions_text() + "D) and " + db.name + " (" +
                   db.dimensions_text() + "D) share no dimension and cannot be blended");
    blend->parameters = {{"alpha", "weight of " + db.name + ": W = (1 - alpha) W_A + alpha W_B", 0.5, -1e6, 1e6}};
    auto& bp = blend->breakpoints;
    bp.insert(bp.end(), da.breakpoints.begin(), da.breakpoints.end());
    bp.insert(bp.end(), db.breakpoints.begin(), db.breakpoints.end());
    if (da.support != db.support) bp.push_back(std::min(da.support, db.support));
    std::sort(bp.begin(), bp.end());
    bp.erase(std::unique(bp.begin(), bp.end()), bp.end());
    blend->separate_derivative = da.separate_derivative || db.separate_derivative;
    blend->from_expression = da.from_expression && db.from_expression;
    blend->origin = KernelOrigin::blend;
    blend->truncations = {da.support};
    if (db.support != da.support) blend->truncations.push_back(db.support);
    blend->functions = std::make_shared<BlendFunctions>(a, b);
    return blend;
}

} // namespace sphkern
