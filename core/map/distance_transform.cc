#include "core/map/distance_transform.h"

#include <algorithm>
#include <cstddef>
#include <limits>

namespace topay {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
// Lines gathered per block in the strided passes: 16 values = one 64-byte cache line per row.
constexpr int kLanes = 16;

// First pass along x: for each cell, the squared distance to the nearest cell of the other
// phase on the same row, by a forward and a backward sweep.
void RowPass(const std::uint8_t* row, int n, float* out) {
  constexpr int kFar = std::numeric_limits<int>::max() / 4;
  int last_free = -kFar;
  int last_occupied = -kFar;
  for (int i = 0; i < n; ++i) {
    const bool occupied = row[i] != 0;
    (occupied ? last_occupied : last_free) = i;
    out[i] = static_cast<float>(i - (occupied ? last_free : last_occupied));
  }
  int next_free = 2 * kFar;
  int next_occupied = 2 * kFar;
  for (int i = n - 1; i >= 0; --i) {
    const bool occupied = row[i] != 0;
    (occupied ? next_occupied : next_free) = i;
    const float best =
        std::min(out[i], static_cast<float>((occupied ? next_free : next_occupied) - i));
    out[i] = best >= static_cast<float>(kFar) ? kInfinity : best * best;
  }
}

// Transforms the run line[begin, end) of one phase in place, with the cells bounding it (of the
// other phase, value 0) as extra sites where they exist.
void TransformRun(std::int32_t* line, int begin, int end, int n, EdtWorkspace* ws) {
  const int length = end - begin;
  // A cell next to a boundary site ends at 1 (values are >= 1), so runs of one or two cells
  // between two boundaries need no envelope.
  if (length <= 2 && begin > 0 && end < n) {
    std::fill(line + begin, line + end, 1);
    return;
  }
  std::int32_t* input = ws->run_input.data();
  input[0] = begin > 0 ? 0 : kNoSite;
  std::copy(line + begin, line + end, input + 1);
  input[length + 1] = end < n ? 0 : kNoSite;
  std::int32_t* output = ws->run_output.data();
  SquaredDistance1d(input, length + 2, output, ws->sites.data(), ws->bound_numerators.data(),
                    ws->bound_denominators.data());
  std::copy(output + 1, output + 1 + length, line + begin);
}

// One line of a y or z pass, in place, run by run.
void TransformLine(std::int32_t* line, const std::uint8_t* occupied, int n, EdtWorkspace* ws) {
  int begin = 0;
  while (begin < n) {
    int end = begin + 1;
    while (end < n && occupied[end] == occupied[begin]) ++end;
    TransformRun(line, begin, end, n, ws);
    begin = end;
  }
}

// Transforms `lanes` lines of `length` samples with sample stride `stride` that start at the
// adjacent cells first_start + lane: gathers them (values and cells), transforms each, and
// scatters the values back.
void StridedBlockPass(float* data, const std::uint8_t* cells, std::int64_t first_start,
                      int lanes, int length, std::int64_t stride, EdtWorkspace* ws) {
  std::int32_t* lines = ws->lines.data();
  std::uint8_t* occupied = ws->occupied.data();
  for (int s = 0; s < length; ++s) {
    const std::int64_t row = first_start + s * stride;
    for (int lane = 0; lane < lanes; ++lane) {
      const float value = data[row + lane];
      lines[lane * length + s] = value == kInfinity ? kNoSite : static_cast<std::int32_t>(value);
      occupied[lane * length + s] = cells[row + lane];
    }
  }
  for (int lane = 0; lane < lanes; ++lane) {
    TransformLine(lines + lane * length, occupied + lane * length, length, ws);
  }
  for (int s = 0; s < length; ++s) {
    float* row = data + first_start + s * stride;
    for (int lane = 0; lane < lanes; ++lane) {
      const std::int32_t value = lines[lane * length + s];
      row[lane] = value == kNoSite ? kInfinity : static_cast<float>(value);
    }
  }
}

// Transforms the lines along axis `axis` (1: y, 2: z) of the x-fastest array that start at
// x in [x_begin, x_end) and, on the remaining axis (z for y lines, y for z lines), in
// [outer_begin, outer_end).
void StridedPass(float* data, const std::uint8_t* cells, const Eigen::Vector3i& dims, int axis,
                 int x_begin, int x_end, int outer_begin, int outer_end, EdtWorkspace* ws) {
  const int nx = dims.x();
  const std::int64_t nxy = std::int64_t{nx} * dims.y();
  const int length = dims(axis);
  const std::int64_t stride = axis == 1 ? nx : nxy;
  // Lines start at every cell with coordinate 0 on `axis`: (x, z) for y lines, (x, y) for z.
  const std::int64_t outer_stride = axis == 1 ? nxy : nx;
  for (int outer = outer_begin; outer < outer_end; ++outer) {
    for (int x = x_begin; x < x_end; x += kLanes) {
      StridedBlockPass(data, cells, outer * outer_stride + x, std::min(kLanes, x_end - x), length,
                       stride, ws);
    }
  }
}

}  // namespace

void SquaredDistance1d(const std::int32_t* f, int n, std::int32_t* d, std::int32_t* sites,
                       std::int64_t* numerators, std::int64_t* denominators) {
  // Lower envelope of the parabolas y = (q - p)^2 + f[p] over the sites: sites[0..k] are the
  // apexes in order; parabola sites[j] is lowest from z_j = numerators[j] / denominators[j]
  // (denominator > 0) to z_{j+1}, with z_0 = -infinity and z_{k+1} = +infinity implicit.
  int k = -1;
  for (int q = 0; q < n; ++q) {
    if (f[q] == kNoSite) continue;
    const std::int64_t fq = std::int64_t{f[q]} + std::int64_t{q} * q;
    // Intersection of parabolas q and v: s = ((f[q] + q^2) - (f[v] + v^2)) / (2q - 2v)
    // (FH 2012, Sec. 3). Pop apexes whose parabola the new one hides: s <= z_k, compared as
    // fractions, N / D <= N_k / D_k  <=>  N D_k <= N_k D (both denominators positive).
    std::int64_t numerator = 0;
    std::int64_t denominator = 1;
    while (k >= 0) {
      const std::int64_t v = sites[k];
      numerator = fq - (std::int64_t{f[v]} + v * v);
      denominator = 2 * (q - v);
      if (k == 0 || numerator * denominators[k] > numerators[k] * denominator) break;
      --k;
    }
    ++k;
    sites[k] = q;
    numerators[k] = numerator;
    denominators[k] = denominator;
  }
  if (k < 0) {
    std::fill_n(d, n, kNoSite);
    return;
  }
  int j = 0;
  for (int q = 0; q < n; ++q) {
    // Advance while z_{j+1} < q, i.e. N_{j+1} < q D_{j+1}.
    while (j < k && numerators[j + 1] < q * denominators[j + 1]) ++j;
    const std::int64_t offset = q - sites[j];
    d[q] = static_cast<std::int32_t>(offset * offset + f[sites[j]]);
  }
}

void SquaredDistanceToOtherPhase(const std::uint8_t* cells, const Eigen::Vector3i& dims,
                                 float* out, EdtWorkspace* workspace) {
  SquaredDistanceToOtherPhaseAt(cells, dims, Eigen::Vector3i::Zero(), dims, out, workspace);
}

void SquaredDistanceToOtherPhaseAt(const std::uint8_t* cells, const Eigen::Vector3i& dims,
                                   const Eigen::Vector3i& needed_begin,
                                   const Eigen::Vector3i& needed_end, float* out,
                                   EdtWorkspace* workspace) {
  const int longest = dims.maxCoeff();
  workspace->lines.resize(static_cast<std::size_t>(kLanes) * longest);
  workspace->occupied.resize(static_cast<std::size_t>(kLanes) * longest);
  workspace->run_input.resize(longest + 2);
  workspace->run_output.resize(longest + 2);
  workspace->sites.resize(longest + 2);
  workspace->bound_numerators.resize(longest + 2);
  workspace->bound_denominators.resize(longest + 2);

  // Each pass reads, per line, only the previous pass's values on that line: the z pass needs
  // the y pass on the needed (x, y) columns at every z, which needs the row pass on every row.
  const int nx = dims.x();
  const std::int64_t rows = std::int64_t{dims.y()} * dims.z();
  for (std::int64_t r = 0; r < rows; ++r) RowPass(cells + r * nx, nx, out + r * nx);
  if (dims.y() > 1) {
    StridedPass(out, cells, dims, 1, needed_begin.x(), needed_end.x(), 0, dims.z(), workspace);
  }
  if (dims.z() > 1) {
    StridedPass(out, cells, dims, 2, needed_begin.x(), needed_end.x(), needed_begin.y(),
                needed_end.y(), workspace);
  }
}

}  // namespace topay
