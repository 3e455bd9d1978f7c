#include "kernels/expression_kernel.hpp"

#include "support/text/printable_text.hpp"

#include "support/error.hpp"
#include "support/io/json_input.hpp"
#include "support/text/value_checks.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <muParser.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <mutex>
#include <sstream>
#include <unordered_map>

namespace sphkern {

namespace {

constexpr double pi = 3.14159265358979323846;

struct Expressions {
    std::string w, dw; // dw empty: numerical derivative
    std::vector<std::string> parameter_names;
    std::vector<double> breakpoints;
    double support = 0;
    bool normalise = false; // "normalise": true: W is f divided by its integral, else f as written
};

// A muparser instance per thread (muparser is not thread-safe), bound to its own variables.
struct Parsers {
    mu::Parser w, dw;
    double q = 0, k = 1;
    std::vector<double> params;

    explicit Parsers(const Expressions& e) : params(e.parameter_names.size())
    {
        for (mu::Parser* p : {&w, &dw}) {
            // muparser's own _pi is 3.141592653589 with GCC: a constant written with it would be 2.5e-13 off.
            p->DefineConst("_pi", pi);
            p->DefineVar("q", &q);
            p->DefineVar("k", &k);
            for (std::size_t i = 0; i < params.size(); ++i) p->DefineVar(e.parameter_names[i], &params[i]);
        }
        w.SetExpr(e.w);
        if (!e.dw.empty()) dw.SetExpr(e.dw);
    }
};

class ExpressionFunctions final : public KernelFunctions {
public:
    explicit ExpressionFunctions(Expressions e) : e_(std::move(e)), id_(next_id_++) {}

    double shape(double q, double k, const double* params) const
    {
        Parsers& p = parsers();
        p.q = q;
        p.k = k;
        for (std::size_t i = 0; i < p.params.size(); ++i) p.params[i] = params[i];
        return p.w.Eval();
    }
    double shape_derivative(double q, double k, const double* params) const
    {
        if (e_.dw.empty()) { // central difference, one-sided at q = 0
            const double h = 1e-6 * std::max(1.0, q);
            return q < h ? (shape(q + h, k, params) - shape(q, k, params)) / h
                         : (shape(q + h, k, params) - shape(q - h, k, params)) / (2 * h);
        }
        Parsers& p = parsers();
        p.q = q;
        p.k = k;
        for (std::size_t i = 0; i < p.params.size(); ++i) p.params[i] = params[i];
        return p.dw.Eval();
    }

    // 1 / integral of f over D-space (f cut at R), for these parameter values.
    double sigma(int dim, const double* params) const
    {
        std::vector<double> key(params, params + e_.parameter_names.size());
        key.push_back(dim);
        std::lock_guard<std::mutex> lock(mutex_);
        auto it = sigma_.find(key);
        if (it != sigma_.end()) return it->second;
        std::vector<double> edges = {0.0};
        for (double b : e_.breakpoints) edges.push_back(b);
        edges.push_back(e_.support);
        double integral = 0;
        for (std::size_t i = 0; i + 1 < edges.size(); ++i)
            integral += boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
                [&](double q) { return shape(q, 1.0, params) * std::pow(q, dim - 1); }, edges[i], edges[i + 1], 15,
                1e-15);
        const double area = dim == 1 ? 2.0 : dim == 2 ? 2 * pi : 4 * pi;
        double value = 1.0 / (area * integral);
        sigma_.emplace(key, value);
        return value;
    }

    // W = factor * f: f as written (the author's constant), unless the file asks sphkern to normalise it.
    double factor(int dim, const double* params) const { return e_.normalise ? sigma(dim, params) : 1.0; }

    double w(double q, int dim, double k, const double* p) const override { return factor(dim, p) * shape(q, k, p); }
    double dw(double q, int dim, double k, const double* p) const override
    {
        return factor(dim, p) * shape_derivative(q, k, p);
    }
    void w_batch(const double* q, double* out, std::size_t n, int dim, double k, const double* p) const override
    {
        const double s = factor(dim, p);
        for (std::size_t i = 0; i < n; ++i) out[i] = s * shape(q[i], k, p);
    }
    void dw_batch(const double* q, double* out, std::size_t n, int dim, double k, const double* p) const override
    {
        const double s = factor(dim, p);
        for (std::size_t i = 0; i < n; ++i) out[i] = s * shape_derivative(q[i], k, p);
    }

private:
    Parsers& parsers() const
    {
        thread_local std::unordered_map<std::uint64_t, std::unique_ptr<Parsers>> cache;
        auto& slot = cache[id_];
        if (!slot) slot = std::make_unique<Parsers>(e_);
        return *slot;
    }

    Expressions e_;
    std::uint64_t id_;
    static inline std::atomic<std::uint64_t> next_id_{1};
    mutable std::mutex mutex_;
    mutable std::map<std::vector<double>, double> sigma_;
};

std::string identifier(const JsonNode& node)
{
    std::string s = node.string();
    if (!is_identifier(s)) node.error("expected a name of up to 64 characters of [a-z0-9_]");
    return s;
}

// Checks an expression's syntax and variables now, so that errors name their JSON path.
void check_expression(const JsonNode& node, const std::string& text, const std::vector<std::string>& names)
{
    try {
        mu::Parser parser;
        double q = 0.5, k = 1;
        std::vector<double> values(names.size(), 0.0);
        parser.DefineConst("_pi", pi);
        parser.DefineVar("q", &q);
        parser.DefineVar("k", &k);
        for (std::size_t i = 0; i < names.size(); ++i) parser.DefineVar(names[i], &values[i]);
        parser.SetExpr(text);
        parser.Eval();
    } catch (const mu::Parser::exception_type& e) {
        node.error("not a valid expression of q, k and the parameters: " + e.GetMsg());
    }
}

// The dimensions, each once, in increasing order.
std::vector<int> read_dimensions(const JsonNode& root)
{
    auto dims = root.at("dimensions");
    dims.expect_array(1, 3);
    std::vector<int> dimensions;
    for (std::size_t i = 0; i < dims.size(); ++i) {
        int d = static_cast<int>(dims[i].integer_in(1, 3));
        if (std::find(dimensions.begin(), dimensions.end(), d) != dimensions.end())
            dims[i].error("dimension " + std::to_string(d) + " listed twice");
        dimensions.push_back(d);
    }
    std::sort(dimensions.begin(), dimensions.end());
    return dimensions;
}

// The shape parameters: names other than q and k, min <= default <= max.
std::vector<KernelParameter> read_parameters(const JsonNode& root)
{
    std::vector<KernelParameter> parameters;
    auto params = root.find("parameters");
    if (!params) return parameters;
    params->expect_array(0, 16);
    for (std::size_t i = 0; i < params->size(); ++i) {
        auto p = (*params)[i];
        p.expect_keys({"name", "description", "default", "min", "max"});
        KernelParameter parameter{identifier(p.at("name")), p.find("description") ? p.at("description").text() : "",
                                  p.at("default").number(), p.at("min").number(), p.at("max").number()};
        if (parameter.name == "q" || parameter.name == "k") p.at("name").error("q and k are taken");
        if (!(parameter.min_value <= parameter.default_value && parameter.default_value <= parameter.max_value))
            p.error("expected min <= default <= max");
        parameters.push_back(parameter);
    }
    return parameters;
}

// Breakpoints strictly increasing inside (0, support).
std::vector<double> read_breakpoints(const JsonNode& root, double support)
{
    std::vector<double> breakpoints;
    auto breaks = root.find("breakpoints");
    if (!breaks) return breakpoints;
    breaks->expect_array(0, 64);
    for (std::size_t i = 0; i < breaks->size(); ++i) {
        double b = (*breaks)[i].number();
        if (b <= 0 || b >= support || (i > 0 && b <= breakpoints.back()))
            (*breaks)[i].error("breakpoints must increase strictly inside (0, support)");
        breakpoints.push_back(b);
    }
    return breakpoints;
}

// Finite values and a positive finite integral with the default parameters, or an error at
// /w. A wrong constant is check's business; a W with no positive integral is no kernel.
void require_normalisable(const JsonNode& root, const KernelDefinition& kernel, const ExpressionFunctions& functions,
                          bool normalise)
{
    std::vector<double> defaults;
    for (const auto& p : kernel.parameters) defaults.push_back(p.default_value);
    for (int dim : kernel.dimensions) {
        double s = functions.sigma(dim, defaults.data());
        if (!std::isfinite(s) || s <= 0)
            root.at("w").error("the integral of w over " + std::to_string(dim) +
                               "D space is not a positive finite number" +
                               (normalise ? ", so it cannot be normalised" : ""));
        for (int i = 0; i <= 60; ++i) {
            double q = 1.5 * kernel.support * i / 60;
            if (!std::isfinite(functions.w(q, dim, 1.0, defaults.data())) ||
                !std::isfinite(functions.dw(q, dim, 1.0, defaults.data()))) {
                std::ostringstream at;
                at << "non-finite value at q = " << q << " (default parameters)";
                root.at("w").error(at.str());
            }
        }
    }
}

} // namespace

std::shared_ptr<const KernelDefinition> load_expression_kernel(const std::filesystem::path& file)
{
    auto document = read_json_file(file);
    JsonNode root(document, file.string());
    root.expect_keys({"$schema", "name", "title", "reference", "support", "dimensions", "parameters", "breakpoints",
                      "w", "dw", "normalise"});
    auto kernel = std::make_shared<KernelDefinition>();
    Expressions e;
    kernel->source = std::filesystem::absolute(file).lexically_normal().string();
    kernel->from_expression = true;
    kernel->origin = KernelOrigin::expression;
    kernel->name = identifier(root.at("name"));
    kernel->title = root.find("title") ? printable_text(root.at("title").string()) : kernel->name;
    kernel->reference = root.find("reference") ? printable_text(root.at("reference").text()) : "";
    kernel->support = e.support = root.at("support").number_in(1e-3, 100);
    kernel->dimensions = read_dimensions(root);
    kernel->parameters = read_parameters(root);
    for (const auto& p : kernel->parameters) e.parameter_names.push_back(p.name);
    kernel->breakpoints = e.breakpoints = read_breakpoints(root, kernel->support);
    e.w = root.at("w").string();
    check_expression(root.at("w"), e.w, e.parameter_names);
    if (auto dw = root.find("dw")) {
        e.dw = dw->string();
        check_expression(*dw, e.dw, e.parameter_names);
    } else {
        kernel->derivative_note = "no \"dw\" expression: dW/dr is a central difference of W (step 1e-6 q)";
    }
    if (auto normalise = root.find("normalise")) e.normalise = normalise->boolean();
    kernel->normalised = e.normalise;
    kernel->truncations = {kernel->support};
    auto functions = std::make_shared<ExpressionFunctions>(e);
    require_normalisable(root, *kernel, *functions, e.normalise);
    kernel->functions = functions;
    return kernel;
}

} // namespace sphkern
