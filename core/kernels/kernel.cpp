#include "kernels/kernel.hpp"

#include "kernels/fourier_transform.hpp"
#include "kernels/second_derivative.hpp"
#include "support/error.hpp"
#include "support/io/json_input.hpp"
#include "support/text/value_checks.hpp"

#include <cmath>
#include <sstream>

namespace sphkern {

Kernel::Kernel(std::shared_ptr<const KernelDefinition> definition, const std::map<std::string, double>& values)
    : definition_(std::move(definition)), f_(definition_->functions.get())
{
    std::vector<std::string> names;
    for (const auto& p : definition_->parameters) {
        names.push_back(p.name);
        values_.push_back(p.default_value);
    }
    for (const auto& [name, value] : values) {
        std::size_t i = 0;
        while (i < names.size() && names[i] != name) ++i;
        if (i == names.size()) {
            std::string message =
                "kernel " + definition_->name + " has no parameter \"" + name + "\"" + did_you_mean(name, names);
            fail_unknown(message + (names.empty() ? "; it has no parameters" : ""));
        }
        const auto& p = definition_->parameters[i];
        if (!std::isfinite(value) || value < p.min_value || value > p.max_value) {
            std::ostringstream s;
            s << "kernel " << definition_->name << ": parameter " << name << " = " << value
              << " is out of range, expected a value in [" << p.min_value << ", " << p.max_value << "]";
            fail_input(s.str());
        }
        values_[i] = value;
    }
}

void Kernel::require_dimension(int dim, const std::string& lattice_name) const
{
    if (!supports(dim))
        fail_input("kernel " + name() + " is defined in " + definition_->dimensions_text() + "D only, not on the " +
                   std::to_string(dim) + "D lattice " + lattice_name);
}

double Kernel::d2w(double q, int dim, double k) const
{
    return f_->has_second_derivative() ? f_->d2w(q, dim, k, values_.data())
                                       : numerical_second_derivative(*this, q, dim, k);
}

double Kernel::fourier(double kh, int dim, double k) const
{
    return f_->has_fourier_transform() ? f_->fourier_transform(kh, dim, k, values_.data())
                                       : fourier_transform_by_quadrature(*this, kh, dim, k);
}

std::string Kernel::label() const
{
    if (values_.empty()) return name();
    std::ostringstream s;
    s << name() << "(";
    for (std::size_t i = 0; i < values_.size(); ++i)
        s << (i ? ", " : "") << definition_->parameters[i].name << "=" << values_[i];
    s << ")";
    return s.str();
}

} // namespace sphkern
