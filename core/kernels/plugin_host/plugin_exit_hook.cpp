#include "kernels/plugin_host/plugin_exit_hook.hpp"

#include "kernels/plugin_host/plugin_call_guard.hpp"
#include "kernels/plugin_host/plugin_faults.hpp"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <link.h>
#include <sys/mman.h>
#include <unistd.h>

namespace sphkern {

namespace {

extern "C" [[noreturn]] void exit_from_plugin(int status)
{
    if (current_plugin_call()) jump_to_recovery_point(exit_in_plugin_jump);
    std::exit(status); // the command line: its exit() check names the plugin
}

extern "C" [[noreturn]] void quick_exit_from_plugin(int status)
{
    if (const PluginCall* call = current_plugin_call()) {
        jump_to_recovery_point(exit_in_plugin_jump);
        end_for_plugin(*call, "called exit() or pthread_exit()"); // no exit() check sees _exit()
    }
    ::_exit(status);
}

#if defined(__x86_64__) && defined(__linux__)
// The library's RELRO range (made read-only after relocation), found by its load address.
struct Range {
    std::uintptr_t begin = 0, end = 0;
};

Range relro_of(std::uintptr_t base)
{
    Range found;
    struct Search {
        std::uintptr_t base;
        Range* range;
    } search{base, &found};
    ::dl_iterate_phdr(
        [](dl_phdr_info* info, std::size_t, void* data) {
            auto* s = static_cast<Search*>(data);
            if (info->dlpi_addr != s->base) return 0;
            for (int i = 0; i < info->dlpi_phnum; ++i)
                if (info->dlpi_phdr[i].p_type == PT_GNU_RELRO)
                    *s->range = {info->dlpi_addr + info->dlpi_phdr[i].p_vaddr,
                                 info->dlpi_addr + info->dlpi_phdr[i].p_vaddr + info->dlpi_phdr[i].p_memsz};
            return 1;
        },
        &search);
    return found;
}

// Writes `target` into the GOT slot at `slot`; a slot in the RELRO range is opened for the
// write and made read-only again, as the loader left it.
void patch(void** slot, void* target, const Range& relro)
{
    const auto at = reinterpret_cast<std::uintptr_t>(slot);
    if (at < relro.begin || at >= relro.end) {
        *slot = target;
        return;
    }
    const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
    auto* start = reinterpret_cast<void*>(at & ~(page - 1));
    if (::mprotect(start, page, PROT_READ | PROT_WRITE) != 0) return;
    *slot = target;
    ::mprotect(start, page, PROT_READ);
}

void redirect_table(const link_map* map, const ElfW(Rela) * table, std::size_t bytes, const ElfW(Sym) * symbols,
                    const char* names, const Range& relro)
{
    for (std::size_t i = 0; i < bytes / sizeof(ElfW(Rela)); ++i) {
        const auto type = ELF64_R_TYPE(table[i].r_info);
        if (type != R_X86_64_JUMP_SLOT && type != R_X86_64_GLOB_DAT) continue;
        const char* name = names + symbols[ELF64_R_SYM(table[i].r_info)].st_name;
        void* target =
            std::strcmp(name, "exit") == 0 ? reinterpret_cast<void*>(exit_from_plugin)
            : std::strcmp(name, "_exit") == 0 || std::strcmp(name, "_Exit") == 0 || std::strcmp(name, "quick_exit") == 0
                ? reinterpret_cast<void*>(quick_exit_from_plugin)
                : nullptr;
        if (target) patch(reinterpret_cast<void**>(map->l_addr + table[i].r_offset), target, relro);
    }
}
#endif

} // namespace

void redirect_plugin_exits(void* handle)
{
#if defined(__x86_64__) && defined(__linux__)
    link_map* map = nullptr;
    if (!handle || ::dlinfo(handle, RTLD_DI_LINKMAP, &map) != 0 || !map) return;
    const ElfW(Rela)* plt = nullptr, *rela = nullptr;
    std::size_t plt_bytes = 0, rela_bytes = 0;
    const ElfW(Sym)* symbols = nullptr;
    const char* names = nullptr;
    for (const ElfW(Dyn)* d = map->l_ld; d->d_tag != DT_NULL; ++d) {
        // The dynamic section's addresses are relocated by the loader on glibc.
        const auto at = d->d_un.d_ptr;
        switch (d->d_tag) {
        case DT_JMPREL: plt = reinterpret_cast<const ElfW(Rela)*>(at); break;
        case DT_PLTRELSZ: plt_bytes = d->d_un.d_val; break;
        case DT_RELA: rela = reinterpret_cast<const ElfW(Rela)*>(at); break;
        case DT_RELASZ: rela_bytes = d->d_un.d_val; break;
        case DT_SYMTAB: symbols = reinterpret_cast<const ElfW(Sym)*>(at); break;
        case DT_STRTAB: names = reinterpret_cast<const char*>(at); break;
        default: break;
        }
    }
    if (!symbols || !names) return;
    const Range relro = relro_of(map->l_addr);
    if (plt) redirect_table(map, plt, plt_bytes, symbols, names, relro);
    if (rela) redirect_table(map, rela, rela_bytes, symbols, names, relro);
#else
    (void)handle;
#endif
}

} // namespace sphkern
