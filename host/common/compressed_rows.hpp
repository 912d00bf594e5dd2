#pragma once
// Records listed each with its row (most often a vertex) gathered row by
// row: row r's records are records[offsets[r] .. offsets[r + 1]), each row's
// in the order listed. A counting sort: one pass counts, one places.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace meshparticles {

template <typename Record>
void to_compressed_rows(const std::vector<std::pair<std::uint32_t, Record>>& listed, std::size_t row_count,
                        std::vector<std::uint32_t>& offsets, std::vector<Record>& records) {
  offsets.assign(row_count + 1, 0);
  for (const auto& entry : listed) ++offsets[entry.first + 1];
  for (std::size_t r = 0; r < row_count; ++r) offsets[r + 1] += offsets[r];
  records.resize(listed.size());
  std::vector<std::uint32_t> next(offsets.begin(), offsets.end() - 1);
  for (const auto& [row, record] : listed) records[next[row]++] = record;
}

}  // namespace meshparticles
