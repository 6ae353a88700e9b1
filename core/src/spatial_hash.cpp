#include "spatial_hash.hpp"

#include <algorithm>
#include <bit>
#include <cassert>

namespace tv::detail {

SpatialHash::SpatialHash(double cellSize) : grid_(cellSize), table_(64) {}

SpatialHash::SpatialHash(const SpatialHash& other)
    : grid_(other.grid_),
      table_(other.table_),
      keys_(other.keys_),
      bucketOf_(other.bucketOf_),
      cells_(other.cells_),
      freeCells_(other.freeCells_),
      regs_(other.regs_),
      large_(other.large_),
      freeLarge_(other.freeLarge_),
      spares_(other.spares_),
      buffers_(other.buffers_),
      occupied_(other.occupied_),
      box_(other.box_),
      onSide_{other.onSide_[0], other.onSide_[1], other.onSide_[2], other.onSide_[3]},
      boxStale_(other.boxStale_) {
  // Vectors copy their sizes, not their capacities, and the buffer pools trade by capacity.
  for (std::size_t k = 0; k < cells_.size(); ++k) cells_[k].reserve(other.cells_[k].capacity());
  for (std::size_t p = 0; p < spares_.size(); ++p) {
    spares_[p].reserve(other.spares_[p].capacity());
    for (std::size_t i = 0; i < spares_[p].size(); ++i)
      spares_[p][i].reserve(other.spares_[p][i].capacity());
  }
  for (std::uint32_t k = 0; k < keys_.size(); ++k)
    if (!cells_[k].empty()) sync(k);
}

SpatialHash& SpatialHash::operator=(const SpatialHash& other) {
  if (this != &other) {
    SpatialHash copy(other);
    *this = std::move(copy);
  }
  return *this;
}

// [SECTION] registration ------------------------------------------------------------------------

void SpatialHash::insert(std::uint32_t slot, std::uint32_t generation, const Rect& r) {
  if (regs_.size() <= slot) regs_.resize(std::size_t{slot} + 1);
  add(slot, generation, r, grid_.cellsHolding(r));
}

void SpatialHash::update(std::uint32_t slot, const Rect& r) {
  Registration& g = regs_[slot];
  const CellRange cells = grid_.cellsHolding(r);
  if (cells != cellsOf(g)) {
    const std::uint32_t generation = generationOf(slot);
    if (!g.large && cells.count() <= static_cast<std::int64_t>(kCachedCells)) {
      shift(slot, generation, r, cells);
    } else {
      drop(slot);
      add(slot, generation, r, cells);
    }
    return;
  }
  if (!g.large) {
    rewrite(slot, r);
    return;
  }
  Grid::forEachCell(cells, [&](Cell c) {
    for (HashEntry& e : cells_[find(c).cell]) {
      if (e.slot() == slot) {
        e.rect = r;
        break;
      }
    }
  });
}

std::uint32_t SpatialHash::generationOf(std::uint32_t slot) const {
  const Registration& g = regs_[slot];
  if (!g.large) return cells_[g.cell[0]][g.at[0]].generation;
  const CellRange& cells = large_[g.cell[0]];
  for (const HashEntry& e : items({cells.x0, cells.y0}))
    if (e.slot() == slot) return e.generation;
  assert(false && "a large item is not in its first cell");
  return 0;
}

void SpatialHash::add(std::uint32_t slot, std::uint32_t generation, const Rect& r,
                      const CellRange& cells) {
  Registration& g = regs_[slot];
  assert(g.nx == 0 && !g.large);
  if (cells.count() > static_cast<std::int64_t>(kCachedCells)) {
    g.large = true;
    if (freeLarge_.empty()) {
      g.cell[0] = static_cast<std::uint32_t>(large_.size());
      large_.push_back(cells);
    } else {
      g.cell[0] = freeLarge_.back();
      freeLarge_.pop_back();
      large_[g.cell[0]] = cells;
    }
  } else {
    g.nx = static_cast<std::uint8_t>(cells.x1 - cells.x0 + 1);
    g.ny = static_cast<std::uint8_t>(cells.y1 - cells.y0 + 1);
  }
  const std::uint32_t tag = slot | (cells.count() > 1 ? HashEntry::kShared : 0u);
  std::size_t n = 0;
  Grid::forEachCell(cells, [&](Cell c) {
    const std::uint32_t k = cellFor(c);
    auto& items = cells_[k];
    if (items.size() == items.capacity()) {
      regrow(items, std::max<std::size_t>(4, 2 * items.size()));
    }
    if (!g.large) {
      g.cell[n] = k;
      g.at[n] = static_cast<std::uint32_t>(items.size());
    }
    ++n;
    items.push_back({r, tag, generation});
    sync(k);
  });
}

// A small item that moves into other cells keeps its entries in the cells it stays in (they only
// get the new rect) and leaves and enters only the cells at the edges: a mover crossing a cell
// line touches one or two cells, not all of them twice.
void SpatialHash::shift(std::uint32_t slot, std::uint32_t generation, const Rect& r,
                        const CellRange& cells) {
  Registration& g = regs_[slot];
  const std::uint32_t tag = slot | (cells.count() > 1 ? HashEntry::kShared : 0u);
  std::uint32_t keptCell[kCachedCells], keptAt[kCachedCells];
  std::size_t kept = 0;
  const std::size_t before = g.count();
  for (std::size_t i = 0; i < before; ++i) {
    if (cells.contains(keys_[g.cell[i]])) {
      keptCell[kept] = g.cell[i];
      keptAt[kept] = g.at[i];
      ++kept;
    }
  }
  // Leave the cells outside the new range. dropAt moves another item's entry into the hole (an
  // item has one entry a cell) and re-points that item, so the kept indices stay right.
  for (std::size_t i = 0; i < before; ++i) {
    if (!cells.contains(keys_[g.cell[i]])) dropAt(g.cell[i], g.at[i]);
  }
  g.nx = static_cast<std::uint8_t>(cells.x1 - cells.x0 + 1);
  g.ny = static_cast<std::uint8_t>(cells.y1 - cells.y0 + 1);
  std::size_t n = 0;
  Grid::forEachCell(cells, [&](Cell c) {
    for (std::size_t j = 0; j < kept; ++j) {
      if (keys_[keptCell[j]] == c) {
        HashEntry& e = cells_[keptCell[j]][keptAt[j]];
        e.rect = r;
        e.tag = tag;
        g.cell[n] = keptCell[j];
        g.at[n] = keptAt[j];
        ++n;
        return;
      }
    }
    const std::uint32_t k = cellFor(c);
    auto& items = cells_[k];
    if (items.size() == items.capacity()) regrow(items, std::max<std::size_t>(4, 2 * items.size()));
    g.cell[n] = k;
    g.at[n] = static_cast<std::uint32_t>(items.size());
    ++n;
    items.push_back({r, tag, generation});
    sync(k);
  });
}

// Forgets every entry of `slot`; its registration is empty afterwards.
void SpatialHash::drop(std::uint32_t slot) {
  Registration& g = regs_[slot];
  if (!g.large) {
    const std::size_t n = g.count();
    // dropAt re-points other items only: this one's remaining indices stay right.
    for (std::size_t i = 0; i < n; ++i) dropAt(g.cell[i], g.at[i]);
    g.nx = g.ny = 0;
    return;
  }
  const CellRange cells = large_[g.cell[0]];
  freeLarge_.push_back(g.cell[0]);
  g = Registration{};
  Grid::forEachCell(cells, [&](Cell c) {
    const std::uint32_t k = find(c).cell;
    assert(k != kNoCell);
    const auto& items = cells_[k];
    const auto it = std::find_if(items.begin(), items.end(),
                                 [&](const HashEntry& e) { return e.slot() == slot; });
    assert(it != items.end());
    dropAt(k, static_cast<std::uint32_t>(it - items.begin()));
  });
}

// Removes the entry at `at` from cell k: the cell's last entry takes its place (and its item
// learns its new index), and a cell left empty is freed.
void SpatialHash::dropAt(std::uint32_t k, std::uint32_t at) {
  auto& items = cells_[k];
  assert(at < items.size());
  if (at + 1 != items.size()) {
    items[at] = items.back();
    repoint(items[at].slot(), k, at);
  }
  items.pop_back();
  if (items.empty()) {
    freeCell(k);
    return;
  }
  // A cell gives its buffer back for the next size down as soon as its entries fit it, so a world
  // whose items come and go returns to the memory it had. (Waiting for a free place in the
  // smaller buffer saves buffer trades when movers cross a busy cell's line, ~1% of a crowd's
  // move, but leaves every cell an item once visited in the larger buffer.)
  const std::size_t smaller = items.capacity() / 2;
  if (smaller >= 4 && items.size() <= smaller) {
    const auto pool = static_cast<std::size_t>(std::countr_zero(smaller));
    if (pool < spares_.size() && !spares_[pool].empty()) regrow(items, smaller);
  }
  sync(k);
}

void SpatialHash::repoint(std::uint32_t slot, std::uint32_t k, std::uint32_t at) {
  Registration& g = regs_[slot];
  if (g.large) return;  // large items find themselves by scanning
  const std::size_t n = g.count();
  for (std::size_t i = 0; i < n; ++i) {
    if (g.cell[i] == k) {
      g.at[i] = at;
      return;
    }
  }
  assert(false && "an entry's item is not registered in its cell");
}

// [SECTION] cells -------------------------------------------------------------------------------

std::uint32_t SpatialHash::cellFor(Cell c) {
  const std::uint32_t found = find(c).cell;
  if (found != kNoCell) return found;
  if ((occupied_ + 1) * 2 > table_.size()) growTable();
  std::uint32_t k;
  if (!freeCells_.empty()) {
    k = freeCells_.back();
    freeCells_.pop_back();
    keys_[k] = c;
  } else {
    k = static_cast<std::uint32_t>(keys_.size());
    keys_.push_back(c);
    cells_.emplace_back();
    bucketOf_.push_back(0);
    // Every cell storage may be free at once: freeing a cell never allocates.
    freeCells_.reserve(keys_.capacity());
  }
  const std::size_t mask = table_.size() - 1;
  std::size_t i = hash(c) & mask;
  while (table_[i].cell != kNoCell) i = (i + 1) & mask;
  table_[i] = {c, cells_[k].data(), 0, k};
  bucketOf_[k] = static_cast<std::uint32_t>(i);
  ++occupied_;
  boxGains(c);
  return k;
}

// Takes an emptied cell out of the table (backward-shift deletion keeps every probe chain
// unbroken without tombstones) and keeps its storage, buffer included, for the next new cell.
void SpatialHash::freeCell(std::uint32_t k) {
  const std::size_t mask = table_.size() - 1;
  std::size_t hole = bucketOf_[k];
  for (std::size_t j = (hole + 1) & mask; table_[j].cell != kNoCell; j = (j + 1) & mask) {
    const std::size_t home = hash(table_[j].key) & mask;
    // Entry j may move into the hole unless its home lies cyclically in (hole, j].
    if (((j - home) & mask) >= ((j - hole) & mask)) {
      table_[hole] = table_[j];
      bucketOf_[table_[hole].cell] = static_cast<std::uint32_t>(hole);
      hole = j;
    }
  }
  table_[hole] = Bucket{};
  freeCells_.push_back(k);
  --occupied_;
  boxLoses(keys_[k]);
}

// A new occupied cell: the box grows to hold it, and a side it lies on counts it.
void SpatialHash::boxGains(Cell c) {
  if (boxStale_) return;  // found again, counts and all, when next read
  if (box_.empty()) {
    box_ = {c.x, c.y, c.x, c.y};
    onSide_[0] = onSide_[1] = onSide_[2] = onSide_[3] = 1;
    return;
  }
  // A cell beyond a side makes a new side holding it alone.
  if (c.x < box_.x0) box_.x0 = c.x, onSide_[0] = 0;
  if (c.x > box_.x1) box_.x1 = c.x, onSide_[1] = 0;
  if (c.y < box_.y0) box_.y0 = c.y, onSide_[2] = 0;
  if (c.y > box_.y1) box_.y1 = c.y, onSide_[3] = 0;
  onSide_[0] += c.x == box_.x0;
  onSide_[1] += c.x == box_.x1;
  onSide_[2] += c.y == box_.y0;
  onSide_[3] += c.y == box_.y1;
}

// An occupied cell emptied: a side left with no occupied cell means the box is too large, and
// the next read finds it again (a crowd's cells empty all the time, a side rarely).
void SpatialHash::boxLoses(Cell c) {
  if (boxStale_) return;
  bool emptied = false;
  if (c.x == box_.x0) emptied |= --onSide_[0] == 0;
  if (c.x == box_.x1) emptied |= --onSide_[1] == 0;
  if (c.y == box_.y0) emptied |= --onSide_[2] == 0;
  if (c.y == box_.y1) emptied |= --onSide_[3] == 0;
  if (emptied) boxStale_ = true;
}

void SpatialHash::recomputeBox() const {
  boxStale_ = false;
  box_ = CellRange{};
  for (std::size_t k = 0; k < keys_.size(); ++k) {
    if (cells_[k].empty()) continue;
    const Cell c = keys_[k];
    if (box_.empty()) {
      box_ = {c.x, c.y, c.x, c.y};
      onSide_[0] = onSide_[1] = onSide_[2] = onSide_[3] = 0;
    } else {
      if (c.x < box_.x0) box_.x0 = c.x, onSide_[0] = 0;
      if (c.x > box_.x1) box_.x1 = c.x, onSide_[1] = 0;
      if (c.y < box_.y0) box_.y0 = c.y, onSide_[2] = 0;
      if (c.y > box_.y1) box_.y1 = c.y, onSide_[3] = 0;
    }
    onSide_[0] += c.x == box_.x0;
    onSide_[1] += c.x == box_.x1;
    onSide_[2] += c.y == box_.y0;
    onSide_[3] += c.y == box_.y1;
  }
}

void SpatialHash::growTable() {
  std::vector<Bucket> table(table_.size() * 2);
  const std::size_t mask = table.size() - 1;
  for (std::uint32_t k = 0; k < keys_.size(); ++k) {
    if (cells_[k].empty()) continue;  // free storage, or the cell being created
    std::size_t i = hash(keys_[k]) & mask;
    while (table[i].cell != kNoCell) i = (i + 1) & mask;
    table[i] = {keys_[k], cells_[k].data(), static_cast<std::uint32_t>(cells_[k].size()), k};
    bucketOf_[k] = static_cast<std::uint32_t>(i);
  }
  table_ = std::move(table);
}

void SpatialHash::sync(std::uint32_t k) {
  Bucket& b = table_[bucketOf_[k]];
  b.data = cells_[k].data();
  b.size = static_cast<std::uint32_t>(cells_[k].size());
}

// A cell's entries live in a buffer of a power-of-two capacity. Buffers are traded through
// spare pools instead of being freed: a cell that grows takes a larger spare and gives back its
// old one, a cell that empties to half gives its buffer back for a smaller one. So the
// heap is only touched when more cells are crowded *at once* than ever before, not each time
// some cell sees its own peak — which in a moving crowd goes on for tens of thousands of ticks.
// A cell leaves a buffer as soon as its entries fit the next size down, so the buffers of a size
// in use are the cells crowded to that size right now.
void SpatialHash::regrow(std::vector<HashEntry>& items, std::size_t capacity) {
  const auto pool = static_cast<std::size_t>(std::countr_zero(capacity));
  reservePools(pool);
  if (spares_[pool].empty()) {
    // Out of spares: make a quarter as many again as this size has in circulation, as a vector
    // grows geometrically, so a new peak must be a quarter higher before the heap is touched
    // again.
    const std::size_t extra = std::max<std::size_t>(1, buffers_[pool] / 4);
    for (std::size_t i = 0; i < extra; ++i) spares_[pool].emplace_back().reserve(capacity);
    buffers_[pool] += extra;
  }
  std::vector<HashEntry> next = std::move(spares_[pool].back());
  spares_[pool].pop_back();
  next.assign(items.begin(), items.end());
  if (items.capacity() > 0) {
    const auto old = static_cast<std::size_t>(std::countr_zero(items.capacity()));
    reservePools(old);
    // Spares beyond half the buffers of that size in use (a world filling up leaves one behind
    // each time a cell outgrows it) go back to the heap: a crowd's cells come and go by far
    // fewer than half at once.
    const std::size_t inUse = buffers_[old] - spares_[old].size();
    if (spares_[old].size() >= inUse / 2 + 16) {
      std::vector<HashEntry>().swap(items);
      --buffers_[old];
    } else {
      items.clear();
      spares_[old].push_back(std::move(items));
    }
  }
  items = std::move(next);
}

void SpatialHash::reservePools(std::size_t pool) {
  // Room for many spares up front, so that trading buffers does not itself allocate.
  while (spares_.size() <= pool) {
    spares_.emplace_back().reserve(256);
    buffers_.push_back(0);
  }
}

std::size_t SpatialHash::memoryBytes() const {
  std::size_t bytes =
      table_.capacity() * sizeof(Bucket) + keys_.capacity() * sizeof(Cell) +
      bucketOf_.capacity() * sizeof(std::uint32_t) +
      cells_.capacity() * sizeof(std::vector<HashEntry>) +
      freeCells_.capacity() * sizeof(std::uint32_t) + regs_.capacity() * sizeof(Registration) +
      large_.capacity() * sizeof(CellRange) + freeLarge_.capacity() * sizeof(std::uint32_t) +
      buffers_.capacity() * sizeof(std::size_t);
  for (const auto& c : cells_) bytes += c.capacity() * sizeof(HashEntry);
  for (const auto& pool : spares_) {
    bytes += pool.capacity() * sizeof(std::vector<HashEntry>);
    for (const auto& b : pool) bytes += b.capacity() * sizeof(HashEntry);
  }
  return bytes;
}

}  // namespace tv::detail
