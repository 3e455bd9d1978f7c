#include "particles/engine/symmetric_pair_pass.hpp"

namespace sphkern {

std::vector<std::vector<PairTile>> tiles_by_colour(const NeighbourGrid& grid)
{
    const std::size_t ny = grid.rows(1), nz = grid.rows(2), per_row = grid.clusters_per_row();
    const bool layers = nz > 1;
    // A tile writes its own rows and the row after them (in its layer, and in the next layer
    // the row before them too): blocks of two rows or more, one block apart, never meet.
    const std::size_t blocks_per_layer = layers ? 4 : 8;
    const std::size_t rows = std::max<std::size_t>(layers ? 2 : 1, (ny + blocks_per_layer - 1) / blocks_per_layer);
    std::vector<std::vector<PairTile>> colours(layers ? 4 : 2);
    for (std::size_t z = 0; z < nz; ++z)
        for (std::size_t y = 0, block = 0; y < ny; y += rows, ++block) {
            const std::size_t first = (z * ny + y) * per_row, last = (z * ny + std::min(ny, y + rows)) * per_row;
            colours[layers ? z % 2 * 2 + block % 2 : block % 2].push_back({first, last, 0});
        }
    std::size_t index = 0;
    for (auto& tiles : colours)
        for (PairTile& tile : tiles) tile.index = index++;
    return colours;
}

} // namespace sphkern
