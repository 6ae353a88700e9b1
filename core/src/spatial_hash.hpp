#pragma once
// The world's spatial hash: which items are registered in which cell, with a copy of each
// item's rect beside it so the broad phase rejects candidates without touching the world's
// slots (the cache misses that dominate a crowd).
//
// - Registration is half-open: an item is in every cell its extent [x, right) × [y, bottom)
//   meets (Grid::cellsHolding), so a tile whose edge lies on a cell line is in one cell, not
//   two or four. Two rects whose interiors overlap still share a cell, and every query reads
//   the cells of its *closed* extent, so nothing a query can find is missed.
// - Re-registration is O(1): each item remembers, for up to kCachedCells cells, the cell and
//   its entry's index there, so an update neither hashes nor scans a cell; an item that stays
//   in the same cells only rewrites its rects.
// - Cells are recycled: a cell that empties leaves the table, its storage (and its entry
//   buffer) is taken by the next new cell, so memory follows the cells occupied *now*, not
//   every cell ever visited. The box that holds every occupied cell (which clips the walks of
//   long moves) is recomputed as cells empty, so the cost of a move does not depend on where
//   items used to be.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "tv/geometry.hpp"
#include "tv/grid.hpp"

namespace tv::detail {

struct HashEntry {
  static constexpr std::uint32_t kShared = 0x80000000u;
  Rect rect;
  std::uint32_t tag;         // slot, | kShared when the item is in more than one cell
  std::uint32_t generation;  // the item's: a candidate becomes a handle without the slots
  [[nodiscard]] std::uint32_t slot() const { return tag & ~kShared; }
  [[nodiscard]] bool shared() const { return (tag & kShared) != 0; }
};

class SpatialHash {
 public:
  static constexpr std::uint32_t kNoCell = 0xFFFFFFFFu;

  explicit SpatialHash(double cellSize);
  // Buckets point into the cells' buffers, so a copy re-points its own.
  SpatialHash(const SpatialHash& other);
  SpatialHash& operator=(const SpatialHash& other);
  SpatialHash(SpatialHash&&) noexcept = default;
  SpatialHash& operator=(SpatialHash&&) noexcept = default;
  ~SpatialHash() = default;

  [[nodiscard]] const Grid& grid() const { return grid_; }

  /// Registers `slot` (not registered yet) with its rect.
  void insert(std::uint32_t slot, std::uint32_t generation, const Rect& r);
  /// Forgets `slot` (registered).
  void erase(std::uint32_t slot) { drop(slot); }
  /// Moves `slot`'s registration to `r`.
  void update(std::uint32_t slot, const Rect& r);

  // -- a move that stays in its cells (most moves of a crowd): no hashing, no cell indices ------
  /// True when `slot` is registered in few enough cells to remember them and `to` is held by
  /// exactly those cells.
  [[nodiscard]] bool staysInCells(std::uint32_t slot, const Rect& to) const {
    const Registration& g = regs_[slot];
    if (g.large) return false;
    const CellRange c = grid_.cellsHolding(to);
    return c.x1 - c.x0 + 1 == g.nx && c.y1 - c.y0 + 1 == g.ny &&
           keys_[g.cell[0]] == Cell{c.x0, c.y0};
  }
  /// With staysInCells: calls f(const HashEntry&) for every entry of the cells `slot` is
  /// registered in (its own included) until f returns true; returns whether one did.
  template <class F>
  [[nodiscard]] bool anyInOwnCells(std::uint32_t slot, F&& f) const {
    const Registration& g = regs_[slot];
    const std::size_t n = g.count();
    for (std::size_t i = 0; i < n; ++i)
      for (const HashEntry& e : cells_[g.cell[i]])
        if (f(e)) return true;
    return false;
  }
  /// Calls f(Cell) for each cell a small item (not large) is registered in.
  template <class F>
  void forEachCellOf(std::uint32_t slot, F&& f) const {
    const Registration& g = regs_[slot];
    const std::size_t n = g.count();
    for (std::size_t i = 0; i < n; ++i) f(keys_[g.cell[i]]);
  }
  /// With staysInCells: `slot`'s registration now holds `to`.
  void rewrite(std::uint32_t slot, const Rect& to) {
    const Registration& g = regs_[slot];
    const std::size_t n = g.count();
    for (std::size_t i = 0; i < n; ++i) cells_[g.cell[i]][g.at[i]].rect = to;
  }

  /// The part of `cells` that can hold items: nothing lies outside liveBox().
  [[nodiscard]] CellRange live(const CellRange& cells) const {
    return {std::max(cells.x0, box_.x0), std::max(cells.y0, box_.y0), std::min(cells.x1, box_.x1),
            std::min(cells.y1, box_.y1)};
  }
  /// Calls f(const HashEntry&) for the entries of every cell of `cells`, row by row, until f
  /// returns true; returns whether one did. An item in several of them is met once in each.
  template <class F>
  [[nodiscard]] bool anyIn(const CellRange& cells, F&& f) const {
    for (std::int64_t cy = cells.y0; cy <= cells.y1; ++cy)
      for (std::int64_t cx = cells.x0; cx <= cells.x1; ++cx)
        for (const HashEntry& e : items({cx, cy}))
          if (f(e)) return true;
    return false;
  }

  /// The entries of a cell; empty when no item is registered there.
  [[nodiscard]] std::span<const HashEntry> items(Cell c) const {
    const Bucket& b = find(c);
    return {b.data, b.size};
  }
  /// A box holding every occupied cell (empty when there is none). It may be looser than the
  /// tightest box for a while after cells empty, never by more than half the cells ever held.
  [[nodiscard]] const CellRange& liveBox() const { return box_; }
  [[nodiscard]] std::size_t occupiedCells() const { return occupied_; }
  /// Bytes held on the heap (capacities, not sizes).
  [[nodiscard]] std::size_t memoryBytes() const;

  /// Calls f(Cell, std::size_t itemCount) for every occupied cell, in a stable order.
  template <class F>
  void forEachOccupiedCell(F&& f) const {
    for (std::size_t k = 0; k < keys_.size(); ++k)
      if (!cells_[k].empty()) f(keys_[k], cells_[k].size());
  }

 private:
  static constexpr std::size_t kCachedCells = 4;

  // Where a slot is registered, in 36 bytes. A small item (at most kCachedCells cells, nearly
  // every item) remembers its cells row by row — the first is the range's top-left, whose key
  // gives the range with nx and ny — and its entry's index in each. A large item keeps its range
  // in large_ (cell[0] says where) and finds its entries by scanning.
  struct Registration {
    std::uint32_t cell[kCachedCells] = {};
    std::uint32_t at[kCachedCells] = {};
    std::uint8_t nx = 0, ny = 0;  // cells across and down; 0 when not registered
    bool large = false;
    [[nodiscard]] std::size_t count() const { return std::size_t{nx} * ny; }
  };
  [[nodiscard]] CellRange cellsOf(const Registration& g) const {
    if (g.large) return large_[g.cell[0]];
    if (g.nx == 0) return {};
    const Cell c = keys_[g.cell[0]];
    return {c.x, c.y, c.x + g.nx - 1, c.y + g.ny - 1};
  }
  // A bucket mirrors its cell's entries (pointer and count), so a probe reads a cell with two
  // dependent loads instead of three; every change to a cell's entries re-syncs it.
  struct Bucket {
    Cell key;
    const HashEntry* data = nullptr;
    std::uint32_t size = 0;
    std::uint32_t cell = kNoCell;
  };

  [[nodiscard]] const Bucket& find(Cell c) const {
    const std::size_t mask = table_.size() - 1;
    for (std::size_t i = hash(c) & mask;; i = (i + 1) & mask) {
      const Bucket& b = table_[i];
      if (b.cell == kNoCell || b.key == c) return b;
    }
  }
  static std::uint64_t hash(Cell c) {
    const std::uint64_t h = static_cast<std::uint64_t>(c.x) * 0x9E3779B97F4A7C15ull +
                            static_cast<std::uint64_t>(c.y) * 0xC2B2AE3D27D4EB4Full;
    return h ^ (h >> 29);
  }

  std::uint32_t cellFor(Cell c);  // creates it
  void freeCell(std::uint32_t k);
  void growTable();
  void sync(std::uint32_t k);
  void add(std::uint32_t slot, std::uint32_t generation, const Rect& r, const CellRange& cells);
  void shift(std::uint32_t slot, std::uint32_t generation, const Rect& r, const CellRange& cells);
  void drop(std::uint32_t slot);
  [[nodiscard]] std::uint32_t generationOf(std::uint32_t slot) const;
  void dropAt(std::uint32_t k, std::uint32_t at);
  void repoint(std::uint32_t slot, std::uint32_t k, std::uint32_t at);
  void regrow(std::vector<HashEntry>& items, std::size_t capacity);
  void reservePools(std::size_t pool);
  void recomputeBox();

  Grid grid_;
  std::vector<Bucket> table_;
  std::vector<Cell> keys_;
  std::vector<std::uint32_t> bucketOf_;  // per cell, its bucket in table_
  std::vector<std::vector<HashEntry>> cells_;
  std::vector<std::uint32_t> freeCells_;  // cell storage that an emptied cell left
  std::vector<Registration> regs_;        // per slot
  std::vector<CellRange> large_;          // the ranges of large items
  std::vector<std::uint32_t> freeLarge_;  // places in large_ to reuse
  std::vector<std::vector<std::vector<HashEntry>>> spares_;  // [log2 capacity]: buffers to trade
  std::vector<std::size_t> buffers_;  // [log2 capacity]: buffers made, in cells or spare
  std::size_t occupied_ = 0;
  CellRange box_;
  std::size_t freedSinceBox_ = 0;
};

}  // namespace tv::detail
