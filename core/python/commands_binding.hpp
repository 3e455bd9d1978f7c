// The commands that the module adapts beside eps, roots and the rest: the kernel author's
// check, a kernel's spectrum, a finite block, the pairing motion (commands_binding.cpp), a
// relaxation (relax_binding.cpp), and the studies (study_binding.cpp), each over its request.
#pragma once

#include <pybind11/pybind11.h>

namespace sphkern {

void bind_kernel_commands(pybind11::module_& m);
void bind_relax(pybind11::module_& m);
void bind_studies(pybind11::module_& m);
void bind_read_particles(pybind11::module_& m);

} // namespace sphkern
