// Example kernel plugin in C++: Lucy's quartic kernel, with its second derivative offered
// through an extension. What a C++ plugin must do differently from a C one:
//  - export the entry with extern "C": a mangled name is not found (sphkern says so);
//  - let no exception leave a kernel function (they are noexcept here);
//  - name the descriptor's fields in declaration order (C++20 designated initialisers).
#include <sphkern/kernel_plugin.h>

#include <cstddef>
#include <cstring>
#include <numbers>

namespace {

constexpr double alpha(int dim)
{
    return dim == 1 ? 5.0 / 4.0 : dim == 2 ? 5.0 / std::numbers::pi : 105.0 / (16.0 * std::numbers::pi);
}

// h^D W(q) = alpha (1 + 3q) (1 - q)^3 for q <= 1.
double w(double q, int dim, double, const double*) noexcept
{
    const double u = q < 1.0 ? 1.0 - q : 0.0;
    return alpha(dim) * (1.0 + 3.0 * q) * u * u * u;
}

// h^(D+1) dW/dr = -12 alpha q (1 - q)^2.
double dw(double q, int dim, double, const double*) noexcept
{
    const double u = q < 1.0 ? 1.0 - q : 0.0;
    return -12.0 * alpha(dim) * q * u * u;
}

// h^(D+2) d2W/dr2 = -12 alpha (1 - q) (1 - 3q).
double d2w(double q, int dim, double, const double*) noexcept
{
    const double u = q < 1.0 ? 1.0 - q : 0.0;
    return -12.0 * alpha(dim) * u * (1.0 - 3.0 * q);
}

// The batch form of a scalar function; q and out may be the same array.
template <double (*f)(double, int, double, const double*) noexcept>
void batch(const double* q, double* out, std::size_t n, int dim, double k, const double* params) noexcept
{
    for (std::size_t i = 0; i < n; ++i) out[i] = f(q[i], dim, k, params);
}

const sphkern_second_derivative second_derivative = {.d2w = d2w, .d2w_batch = batch<d2w>};

const void* extension(const char* id)
{
    return std::strcmp(id, SPHKERN_EXTENSION_SECOND_DERIVATIVE) == 0 ? &second_derivative : nullptr;
}

const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .flags = 0,
    .name = "lucy_quartic",
    .title = "Lucy's quartic kernel (1 + 3q)(1 - q)^3",
    .reference = "Lucy, Astron. J. 82 (1977) 1013",
    .support = 1.0,
    .dimensions = SPHKERN_DIM(1) | SPHKERN_DIM(2) | SPHKERN_DIM(3),
    .parameter_count = 0,
    .parameters = nullptr,
    .breakpoint_count = 0,
    .breakpoints = nullptr,
    .w = w,
    .dw = dw,
    .w_batch = batch<w>,
    .dw_batch = batch<dw>,
    .get_extension = extension,
    .reserved = {},
};

} // namespace

extern "C" SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
