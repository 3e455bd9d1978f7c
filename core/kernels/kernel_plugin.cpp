#include "kernels/kernel_plugin.hpp"

#include "support/process/resource_errors.hpp"
#include "support/text/printable_text.hpp"

#include "kernels/plugin_file.hpp"
#include "kernels/plugin_host/plugin_call_guard.hpp"
#include "kernels/plugin_host/plugin_exit_hook.hpp"
#include "kernels/plugin_host/plugin_faults.hpp"
#include "kernels/plugin_host/plugin_host.hpp"
#include "kernels/plugin_host/plugin_watchdog.hpp"
#include "kernels/plugin_probe_cache.hpp"
#include "support/error.hpp"
#include "support/io/results_output.hpp"
#include "support/process/interruption.hpp"
#include "support/process/isolated_call.hpp"
#include "support/text/value_checks.hpp"

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include <boost/dll/library_info.hpp>
#include <boost/dll/shared_library.hpp>
#include <cerrno>
#include <fmt/format.h>

#include <atomic>
#include <csetjmp>
#include <cstddef>
#include <cstring>

#include <cmath>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <sstream>
#include <sys/stat.h>
#include <type_traits>
#include <unistd.h>

namespace sphkern {

namespace {

bool valid_identifier(const char* s) { return s && is_identifier(std::string_view(s, strnlen(s, 65))); }

bool valid_text(const char* s)
{
    if (!s) return false;
    for (std::size_t n = 0; s[n]; ++n)
        if (n > 4096) return false;
    return true;
}

// A plugin's constructors run inside the load: whatever folder they move the process to, it
// is moved back, so that relative output paths keep meaning the folder they were given in. The
// folder is kept as its path and identity, not as a descriptor: a constructor may close every
// descriptor (and a number it freed may be another file's by the time we would close it).
class KeepWorkingFolder {
public:
    KeepWorkingFolder()
    {
        std::error_code error;
        path_ = std::filesystem::current_path(error);
        known_ = !error && ::stat(".", &identity_) == 0;
    }
    ~KeepWorkingFolder()
    {
        if (!known_ || here()) return;
        if (::chdir(path_.c_str()) != 0 || !here())
            spdlog::warn("cannot return to the working folder {} after loading a plugin", path_.string());
    }
    KeepWorkingFolder(const KeepWorkingFolder&) = delete;
    KeepWorkingFolder& operator=(const KeepWorkingFolder&) = delete;

private:
    bool here() const
    {
        struct stat now {};
        return ::stat(".", &now) == 0 && now.st_dev == identity_.st_dev && now.st_ino == identity_.st_ino;
    }
    std::filesystem::path path_;
    struct stat identity_ {};
    bool known_ = false;
};

// The dynamic loader's own words ("undefined symbol: f") from Boost.DLL's message, which wraps
// them ("load() failed (dlerror system message: PATH: undefined symbol: f): Bad file
// descriptor", the errno being stale); the whole message where it has no such part.
std::string loader_reason(std::string what, const std::string& path)
{
    const std::string marker = "dlerror system message: ";
    const auto begin = what.find(marker), end = what.rfind("): ");
    if (begin != std::string::npos && end != std::string::npos && end > begin)
        what = what.substr(begin + marker.size(), end - begin - marker.size());
    if (what.starts_with(path + ": ")) what.erase(0, path.size() + 2);
    return what;
}

// Loads `path` (a /proc/self/fd name); `name` is the file as the user gave it.
std::shared_ptr<boost::dll::shared_library> open_library(const std::string& path, const std::string& name)
{
    const KeepWorkingFolder keep;
    try {
        return std::make_shared<boost::dll::shared_library>(boost::dll::fs::path(path),
                                                            boost::dll::load_mode::rtld_now |
                                                                boost::dll::load_mode::rtld_local);
    } catch (const std::exception& e) {
        if (errno == EMFILE || errno == ENFILE) fail_resource(errno, name + ": cannot be opened");
        throw Error(ExitCode::plugin, name + ": not a loadable shared library: " + loader_reason(e.what(), path));
    }
}

// The dynamic symbols of a library, for hints; empty when it cannot be read.
std::vector<std::string> exported_symbols(const std::string& file)
{
    try {
        return boost::dll::library_info(boost::dll::fs::path(file)).symbols();
    } catch (const std::exception&) {
        return {};
    }
}

const void* call_entry(const boost::dll::shared_library& library, const std::string& file)
{
    if (!library.has(SPHKERN_ENTRY_NAME)) {
        std::string hint;
        for (const auto& symbol : exported_symbols(file))
            if (symbol.find(SPHKERN_ENTRY_NAME) != std::string::npos && symbol != SPHKERN_ENTRY_NAME) {
                hint = " (it exports the C++ name " + symbol + ": declare the entry function extern \"C\")";
                break;
            }
        throw Error(ExitCode::plugin,
                    file + ": not a sphkern kernel plugin (no exported " SPHKERN_ENTRY_NAME ")" + hint);
    }
    auto entry = library.get<const void*()>(SPHKERN_ENTRY_NAME);
    const void* descriptor = entry();
    if (!descriptor) throw Error(ExitCode::plugin, file + ": " SPHKERN_ENTRY_NAME " returned no descriptor");
    return descriptor;
}

// The layout of ABI 1, frozen: plugins built against it keep loading.
struct DescriptorV1 {
    uint32_t abi_version;
    const char* name;
    const char* title;
    const char* reference;
    double support;
    uint32_t dimensions;
    uint32_t flags;
    uint32_t parameter_count;
    const sphkern_kernel_parameter* parameters;
    uint32_t breakpoint_count;
    const double* breakpoints;
    sphkern_kernel_fn w;
    sphkern_kernel_fn dw;
    sphkern_kernel_batch_fn w_batch;
    sphkern_kernel_batch_fn dw_batch;
};

constexpr std::size_t required_v2_size = offsetof(sphkern_kernel_descriptor, get_extension);

// The functions of a plugin: its descriptor's pointers, and the library they live in. Every
// call runs under a PluginCallGuard, so that a crash, exit() or hang in it names the plugin.
// In a library host a crash raises instead (plugin_faults), and the plugin is not called again.
class PluginFunctions final : public KernelFunctions {
public:
    PluginFunctions(std::shared_ptr<boost::dll::shared_library> library, const PluginDescriptor& d,
                    const std::string& file)
        : library_(std::move(library)), d_(d), w_(file, d.fields.name, "W"), dw_(file, d.fields.name, "dW"),
          w_batch_(file, d.fields.name, "the batch W"), dw_batch_(file, d.fields.name, "the batch dW"),
          w_dw_batch_(file, d.fields.name, "the fused W and dW"), d2w_(file, d.fields.name, "d2W"),
          fourier_(file, d.fields.name, "the Fourier transform")
    {}
    double w(double q, int dim, double k, const double* p) const override
    {
        return call(w_, [&] { return d_.fields.w(q, dim, k, p); });
    }
    double dw(double q, int dim, double k, const double* p) const override
    {
        return call(dw_, [&] { return d_.fields.dw(q, dim, k, p); });
    }
    void w_batch(const double* q, double* out, std::size_t n, int dim, double k, const double* p) const override
    {
        call(w_batch_, [&] { d_.fields.w_batch(q, out, n, dim, k, p); });
    }
    void dw_batch(const double* q, double* out, std::size_t n, int dim, double k, const double* p) const override
    {
        call(dw_batch_, [&] { d_.fields.dw_batch(q, out, n, dim, k, p); });
    }
    void w_dw_batch(const double* q, double* w, double* dw, std::size_t n, int dim, double k,
                    const double* p) const override
    {
        if (!d_.fused) return KernelFunctions::w_dw_batch(q, w, dw, n, dim, k, p);
        call(w_dw_batch_, [&] { d_.fused->w_dw(q, w, dw, n, dim, k, p); });
    }
    bool has_second_derivative() const override { return d_.second != nullptr; }
    double d2w(double q, int dim, double k, const double* p) const override
    {
        return call(d2w_, [&] { return d_.second->d2w(q, dim, k, p); });
    }
    bool has_fourier_transform() const override { return d_.fourier != nullptr; }
    double fourier_transform(double kh, int dim, double k, const double* p) const override
    {
        return call(fourier_, [&] { return d_.fourier->transform(kh, dim, k, p); });
    }

private:
    // f() inside the guard; where faults are recoverable, a crash in it comes back here as the
    // signal (sigsetjmp saves no mask: no system call per call) and is thrown.
    template <class F>
    auto call(const PluginCall& function, F&& f) const -> decltype(f())
    {
        if (const PluginCall* where = crashed_in_.load()) refuse_after_crash(*where);
        PluginCallGuard in(function);
        if (!plugin_faults_recoverable()) return f();
        sigjmp_buf point;
        if (const int jump = sigsetjmp(point, 0)) {
            crashed_signal_ = jump;
            crashed_in_ = &function;
            throw Error(ExitCode::plugin, std::string(function.plugin()) + " " + what_happened(jump) + " in " +
                                              function.function() + "; it is not called again in this process");
        }
        set_recovery_point(&point);
        if constexpr (std::is_void_v<decltype(f())>) {
            f();
            set_recovery_point(nullptr);
        } else {
            const auto value = f();
            set_recovery_point(nullptr);
            return value;
        }
    }
    [[noreturn]] void refuse_after_crash(const PluginCall& where) const
    {
        throw Error(ExitCode::plugin, std::string(where.plugin()) + " " + what_happened(crashed_signal_.load()) +
                                          " in " + where.function() +
                                          " earlier; it is not called again in this process");
    }
    static std::string what_happened(int jump)
    {
        return jump == exit_in_plugin_jump ? "called exit()" : crash_description(jump);
    }

    std::shared_ptr<boost::dll::shared_library> library_; // keeps the descriptor and its functions mapped
    PluginDescriptor d_;
    PluginCall w_, dw_, w_batch_, dw_batch_, w_dw_batch_, d2w_, fourier_;
    mutable std::atomic<const PluginCall*> crashed_in_{nullptr};
    mutable std::atomic<int> crashed_signal_{0};
};

} // namespace

double plugin_probe_timeout() { return plugin_timeout_seconds(); }

namespace {

// The layout: ABI 1 (frozen) or ABI 2 of any struct_size, read into the ABI 2 form.
std::string normalise_descriptor(const void* raw, PluginDescriptor& out)
{
    uint32_t major = 0;
    std::memcpy(&major, raw, sizeof major);
    if (major == 1) {
        DescriptorV1 v1{};
        std::memcpy(&v1, raw, sizeof v1);
        out.abi_major = 1;
        auto& f = out.fields;
        f.flags = v1.flags;
        f.name = v1.name;
        f.title = v1.title;
        f.reference = v1.reference;
        f.support = v1.support;
        f.dimensions = v1.dimensions;
        f.parameter_count = v1.parameter_count;
        f.parameters = v1.parameters;
        f.breakpoint_count = v1.breakpoint_count;
        f.breakpoints = v1.breakpoints;
        f.w = v1.w;
        f.dw = v1.dw;
        f.w_batch = v1.w_batch;
        f.dw_batch = v1.dw_batch;
        return {};
    }
    if (major != SPHKERN_KERNEL_ABI_MAJOR)
        return "ABI version " + std::to_string(major) + ", this sphkern reads versions 1 and " +
               std::to_string(SPHKERN_KERNEL_ABI_MAJOR) + " (rebuild the plugin against this sphkern)";
    const auto* d = static_cast<const sphkern_kernel_descriptor*>(raw);
    if (d->struct_size < required_v2_size || d->struct_size > 4096)
        return "struct_size " + std::to_string(d->struct_size) + " is not a descriptor size (expected at least " +
               std::to_string(required_v2_size) + "; fill it with SPHKERN_DESCRIPTOR_VERSION)";
    out.abi_major = major;
    out.abi_minor = d->abi_minor;
    // Only the fields the plugin's own header had: a smaller struct leaves the rest zero.
    std::memcpy(&out.fields, raw, std::min<std::size_t>(d->struct_size, sizeof out.fields));
    return {};
}

// The extensions the plugin offers, each with its functions.
std::string find_extensions(PluginDescriptor& out)
{
    const auto* d = &out.fields;
    if (!d->get_extension) return {};
    if (const void* e = d->get_extension(SPHKERN_EXTENSION_SECOND_DERIVATIVE)) {
        out.second = static_cast<const sphkern_second_derivative*>(e);
        if (!out.second->d2w || !out.second->d2w_batch) return "the second-derivative extension has a null function";
    }
    if (const void* e = d->get_extension(SPHKERN_EXTENSION_FOURIER_TRANSFORM)) {
        out.fourier = static_cast<const sphkern_fourier_transform*>(e);
        if (!out.fourier->transform) return "the Fourier-transform extension has a null function";
    }
    if (const void* e = d->get_extension(SPHKERN_EXTENSION_FUSED_EVALUATION)) {
        out.fused = static_cast<const sphkern_fused_evaluation*>(e);
        if (!out.fused->w_dw) return "the fused-evaluation extension has a null function";
    }
    return {};
}

std::string check_parameters_and_breakpoints(const sphkern_kernel_descriptor* d)
{
    if (d->parameter_count > 16 || (d->parameter_count > 0 && !d->parameters))
        return "at most 16 parameters, with a parameter array";
    for (uint32_t i = 0; i < d->parameter_count; ++i) {
        const auto& p = d->parameters[i];
        if (!valid_identifier(p.name) || !valid_text(p.description))
            return "parameter " + std::to_string(i) + ": name must be [a-z0-9_]+ and description a C string";
        if (!std::isfinite(p.min_value) || !std::isfinite(p.max_value) || !std::isfinite(p.default_value) ||
            p.min_value > p.default_value || p.default_value > p.max_value)
            return std::string("parameter ") + p.name + ": needs finite min <= default <= max";
    }
    if (d->breakpoint_count > 64 || (d->breakpoint_count > 0 && !d->breakpoints))
        return "at most 64 breakpoints, with a breakpoint array";
    for (uint32_t i = 0; i < d->breakpoint_count; ++i) {
        double b = d->breakpoints[i];
        if (!std::isfinite(b) || b <= 0 || b >= d->support || (i > 0 && b <= d->breakpoints[i - 1]))
            return "breakpoints must increase strictly inside (0, R)";
    }
    return {};
}

// Every field but the functions' values.
std::string validate_descriptor_fields(PluginDescriptor& out)
{
    const auto* d = &out.fields;
    if ((d->flags & ~uint32_t{SPHKERN_KERNEL_KNOWN_FLAGS}) != 0)
        return fmt::format("flags 0x{:x} has bits this sphkern does not define (known: 0x{:x})", d->flags,
                           SPHKERN_KERNEL_KNOWN_FLAGS);
    if (auto reason = find_extensions(out); !reason.empty()) return reason;
    if (!valid_identifier(d->name)) return "name must be 1 to 64 characters of [a-z0-9_]";
    if (!valid_text(d->title) || !valid_text(d->reference)) return "title and reference must be C strings";
    if (!std::isfinite(d->support) || d->support <= 0 || d->support > 100)
        return "support R must be a finite number in (0, 100]";
    if (d->dimensions == 0 || (d->dimensions & ~(SPHKERN_DIM(1) | SPHKERN_DIM(2) | SPHKERN_DIM(3))) != 0)
        return "dimensions must be a non-empty subset of 1, 2, 3";
    if (auto reason = check_parameters_and_breakpoints(d); !reason.empty()) return reason;
    if (!d->w || !d->dw || !d->w_batch || !d->dw_batch) return "a kernel function pointer is null";
    return {};
}

// The functions at 61 q x 4 k in each dimension: finite, and batch equal to scalar.
std::string probe_descriptor_functions(const PluginDescriptor& out)
{
    const auto* d = &out.fields;
    std::vector<double> params;
    for (uint32_t i = 0; i < d->parameter_count; ++i) params.push_back(d->parameters[i].default_value);
    const int steps = 60;
    std::vector<double> qs(steps + 1), batch_w(steps + 1), batch_dw(steps + 1), batch_d2w(steps + 1),
        fused_w(steps + 1), fused_dw(steps + 1);
    for (int i = 0; i <= steps; ++i) qs[i] = 1.5 * d->support * i / steps;
    auto disagree = [](double a, double b) { return std::abs(a - b) > 1e-12 * (1 + std::abs(b)); };
    for (int dim = 1; dim <= 3; ++dim) {
        if (!(d->dimensions & SPHKERN_DIM(dim))) continue;
        for (double k : {0.9, 1.0, 1.1, 1.25}) {
            d->w_batch(qs.data(), batch_w.data(), qs.size(), dim, k, params.data());
            d->dw_batch(qs.data(), batch_dw.data(), qs.size(), dim, k, params.data());
            if (out.second) out.second->d2w_batch(qs.data(), batch_d2w.data(), qs.size(), dim, k, params.data());
            if (out.fused)
                out.fused->w_dw(qs.data(), fused_w.data(), fused_dw.data(), qs.size(), dim, k, params.data());
            for (int i = 0; i <= steps; ++i) {
                double w = d->w(qs[i], dim, k, params.data()), dw = d->dw(qs[i], dim, k, params.data());
                double d2w = out.second ? out.second->d2w(qs[i], dim, k, params.data()) : 0.0;
                double transform = out.fourier ? out.fourier->transform(2 * qs[i], dim, k, params.data()) : 0.0;
                std::ostringstream at;
                at << " at q = " << qs[i] << ", D = " << dim << ", k = " << k;
                if (!std::isfinite(w) || !std::isfinite(dw) || !std::isfinite(d2w))
                    return "non-finite value" + at.str();
                if (!std::isfinite(transform))
                    return "non-finite Fourier transform at kh = " + std::to_string(2 * qs[i]);
                if (disagree(batch_w[i], w) || disagree(batch_dw[i], dw) || (out.second && disagree(batch_d2w[i], d2w)))
                    return "batch and scalar functions disagree" + at.str();
                if (out.fused && (disagree(fused_w[i], w) || disagree(fused_dw[i], dw)))
                    return "the fused and scalar functions disagree" + at.str();
            }
        }
    }
    return {};
}

} // namespace

std::string read_kernel_descriptor(const void* raw, PluginDescriptor& out, DescriptorCheck check)
{
    out = PluginDescriptor{};
    if (auto reason = normalise_descriptor(raw, out); !reason.empty()) return reason;
    if (auto reason = validate_descriptor_fields(out); !reason.empty()) return reason;
    return check == DescriptorCheck::with_functions ? probe_descriptor_functions(out) : std::string{};
}

namespace {

// The kernel name a probe found, and whether the probe ran now, in a child (else the cache knew it).
struct ProbeVerdict {
    std::string name;
    bool in_child = false;
};

// Probes the open file in a child (unless the cache knows it) and returns its kernel name.
ProbeVerdict probe_open_plugin(const PluginFile& plugin)
{
    const std::string& name = plugin.name();
    auto& cache = PluginProbeCache::instance();
    if (auto known = cache.passed(name, &plugin.status())) return {*known, false};

    spdlog::debug("probing {}", name);
    auto verdict = run_isolated(
        [&]() -> std::string {
            try {
                auto library = open_library(plugin.loader_path(), name);
                PluginDescriptor d;
                auto reason = read_kernel_descriptor(call_entry(*library, name), d);
                return reason.empty() ? std::string("+") + d.fields.name
                                      : name + ": invalid kernel descriptor: " + reason;
            } catch (const Error& e) {
                return e.what(); // already names the file
            }
        },
        plugin_probe_timeout());
    if (auto* failure = std::get_if<IsolatedFailure>(&verdict))
        throw Error(ExitCode::plugin, name + ": plugin " + failure->reason);
    const auto& answer = std::get<std::string>(verdict);
    if (answer.empty() || answer[0] != '+') throw Error(ExitCode::plugin, answer);
    if (plugin.unchanged()) cache.record(name, answer.substr(1), &plugin.status());
    return {answer.substr(1), true};
}

// The name the cache gave is not the descriptor's (a cache copied or edited by hand), while the
// file is the one probed: the host has just validated the whole descriptor, so the entry heals.
bool heal_cached_name(const PluginFile& opened, const ProbeVerdict& probe, const std::string& kernel_name)
{
    if (probe.in_child || probe.name == kernel_name || !opened.unchanged()) return false;
    spdlog::debug("the plugin probe cache named {} kernel {}, its descriptor says {}: entry replaced", opened.name(),
                  printable_text(probe.name), kernel_name);
    auto& cache = PluginProbeCache::instance();
    cache.record(opened.name(), kernel_name, &opened.status());
    cache.save();
    return true;
}

} // namespace

std::string probe_kernel_plugin(const std::filesystem::path& file) { return probe_open_plugin(PluginFile(file)).name; }

std::shared_ptr<const KernelDefinition> load_kernel_plugin(const std::filesystem::path& file)
{
    host_plugins();
    PluginFile opened(file);
    const std::string& name = opened.name();
    const ProbeVerdict probe = probe_open_plugin(opened);
    const std::string& kernel_name = probe.name;
    // The constructors and the entry run here too, guarded; the functions' probe points run
    // once per load: here only if the child did not already run them on this same open file.
    const PluginCall loading(name, kernel_name, "its constructors or entry function");
    std::shared_ptr<boost::dll::shared_library> library;
    PluginDescriptor descriptor;
    std::string reason;
    {
        PluginCallGuard in(loading);
        library = open_library(opened.loader_path(), name);
        redirect_plugin_exits(library->native());
        opened.keep();
        reason = read_kernel_descriptor(call_entry(*library, name), descriptor,
                                        probe.in_child ? DescriptorCheck::fields : DescriptorCheck::with_functions);
    }
    if (!reason.empty()) throw Error(ExitCode::plugin, name + ": invalid kernel descriptor: " + reason);
    // Probe and load read one open file; written to in between, it is not used.
    if (!opened.unchanged() ||
        (kernel_name != descriptor.fields.name && !heal_cached_name(opened, probe, descriptor.fields.name))) {
        PluginProbeCache::instance().forget(name);
        PluginProbeCache::instance().save();
        throw Error(ExitCode::plugin, name + ": the plugin changed while it was loaded; run again");
    }
    const auto* d = &descriptor.fields;
    // The library's constructors ran in this process: take the signals and stdout back.
    restore_interrupt_handlers();
    check_results_output();
    auto plugin = std::make_shared<KernelDefinition>();
    plugin->source = std::filesystem::absolute(file).lexically_normal().string();
    plugin->name = d->name;
    plugin->title = printable_text(d->title);
    plugin->reference = printable_text(d->reference);
    plugin->support = d->support;
    for (int dim = 1; dim <= 3; ++dim)
        if (d->dimensions & SPHKERN_DIM(dim)) plugin->dimensions.push_back(dim);
    for (uint32_t i = 0; i < d->parameter_count; ++i) {
        const auto& p = d->parameters[i];
        plugin->parameters.push_back(
            {p.name, printable_text(p.description), p.default_value, p.min_value, p.max_value});
    }
    plugin->breakpoints.assign(d->breakpoints, d->breakpoints + d->breakpoint_count);
    plugin->separate_derivative = (d->flags & SPHKERN_KERNEL_SEPARATE_DERIVATIVE) != 0;
    plugin->truncations = {d->support};
    plugin->abi = fmt::format("{}.{}", descriptor.abi_major, descriptor.abi_minor);
    plugin->functions = std::make_shared<PluginFunctions>(std::move(library), descriptor, name);
    return plugin;
}

} // namespace sphkern
