// One block request (the command line's `block`): direct SPH sums over a finite block of
// lattice cells, with per-particle results for files.
#pragma once

#include "analysis/gradient_form.hpp"
#include "block/particle_block.hpp"
#include "kernels/kernel.hpp"
#include "lattices/lattice.hpp"
#include "requests/evaluation_inputs.hpp"
#include "support/text/value_checks.hpp"

#include <nlohmann/json_fwd.hpp>

#include <ostream>
#include <vector>

namespace sphkern {

struct BlockRequest {
    double k = 0;
    std::vector<long long> cells; // along the basis vectors, as many as the lattice's dimension (the last is vertical)
    bool periodic = false;        // lateral sides
    GradientForm form = GradientForm::sum;
    int threads = 0; // 0: every core
    VolumeCoefficientInput a_p = std::string("voronoi");
};

// How the front end names each value in its errors: the size as given ("--size 4,4").
struct BlockSources {
    ValueSource size, threads, k;
};

// Every value that does not need the kernel or lattice; an Error naming its source.
void check_block_request(const BlockRequest& request, const BlockSources& sources);

struct BlockRun {
    BlockOptions options; // as evaluated: a_p resolved
    BlockResult result;
    double pairs_per_second = 0; // a pair counted once, though it feeds both sums
};

BlockRun run_block(const BlockRequest& request, const BlockSources& sources, const Kernel& kernel,
                   const Lattice& lattice);

// The document `sphkern block --json` prints (without provenance and inputs).
nlohmann::json block_document(const BlockRun& run, const Kernel& kernel, const Lattice& lattice);
// The text `sphkern block` prints, on the results file.
void print_block(const BlockRun& run, const Kernel& kernel, const Lattice& lattice);
// Per-particle results: a legacy VTK file (ParaView), ParaView's XML UnstructuredGrid (.vtu,
// point data eps_rho, eps_gradp and layer, named as the CSV's columns), CSV.
void write_block_vtk(std::ostream& out, const BlockResult& result);
void write_block_vtu(std::ostream& out, const BlockResult& result);
void write_block_csv(std::ostream& out, const BlockResult& result);

} // namespace sphkern
