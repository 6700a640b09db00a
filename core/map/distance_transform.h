#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Core>

namespace topay {

/// Squared distance (cells^2) meaning "no site on this line / in this grid".
inline constexpr std::int32_t kNoSite = std::numeric_limits<std::int32_t>::max();

/// Scratch memory of the distance transform, reused across lines and across builds so the
/// transform allocates nothing per line (and nothing at all once warmed up). Not thread safe:
/// one workspace per thread.
struct EdtWorkspace {
  std::vector<std::int32_t> lines;     ///< A block of gathered lines, line after line.
  std::vector<std::uint8_t> occupied;  ///< The cells of those lines.
  std::vector<std::int32_t> run_input;   ///< One run of a line plus its two boundary sites.
  std::vector<std::int32_t> run_output;
  std::vector<std::int32_t> sites;     ///< Lower envelope: parabola apexes (v in the paper).
  std::vector<std::int64_t> bound_numerators;    ///< Lower envelope: boundaries between
  std::vector<std::int64_t> bound_denominators;  ///< parabolas (z in the paper), as fractions.
};

/// One-dimensional squared distance transform of a sampled function, by the lower envelope of
/// parabolas (Felzenszwalb & Huttenlocher 2012, "Distance Transforms of Sampled Functions",
/// Algorithm 1):  d[q] = min_p ((q - p)^2 + f[p])  for q, p in [0, n).
/// f[p] = kNoSite marks "no site at p"; if every f is kNoSite, so is every d. Exact integer
/// arithmetic (the parabola intersections are kept as fractions and compared by cross
/// multiplication); needs 0 <= f < 2^28 and n < 2^15. `sites`, `numerators`, `denominators` are
/// scratch of at least n entries each; f and d must not alias.
void SquaredDistance1d(const std::int32_t* f, int n, std::int32_t* d, std::int32_t* sites,
                       std::int64_t* numerators, std::int64_t* denominators);

/// Exact squared Euclidean distance transforms of both phases of a binary grid at once, in cell
/// units: out[i] receives the squared distance between the centre of cell i and the centre of
/// the nearest cell of the other phase (for a free cell the nearest occupied cell, for an
/// occupied cell the nearest free cell), or kNoSite if there is none. `cells` holds
/// dims.prod() values (0 free, nonzero occupied) stored x fastest, index (iz ny + iy) nx + ix;
/// dims.z() = 1 for a 2D grid. Squared distances are stored as floats (exact: integers below
/// 2^24), kNoSite as +infinity.
///
/// Method: Felzenszwalb & Huttenlocher 2012, Sec. 5, separable over the axes, for the outside
/// transform (sites: occupied cells) and the inside transform (sites: free cells) in one
/// array. The first pass (along x) is the linear two-sweep scan for the nearest cell of the
/// other phase. In the later passes a line splits into maximal runs of one phase: within a run
/// the sites of that run's transform are exactly the two cells bounding the run (value 0) plus
/// the run's own cells with their values so far; every site beyond a bounding cell is farther
/// than that cell. So each run is transformed on its own, with its two boundary sites: one 1-D
/// transform per cell and pass for both phases together. Passes along y and z gather blocks of
/// 16 adjacent lines into contiguous scratch (cache-line sized reads).
void SquaredDistanceToOtherPhase(const std::uint8_t* cells, const Eigen::Vector3i& dims,
                                 float* out, EdtWorkspace* workspace);

/// SquaredDistanceToOtherPhase computed only as far as the cells in [needed_begin,
/// needed_end) (cell indices per axis) need it: the row pass on every row, the y pass on the
/// lines through the needed x range (every z), the z pass on the lines through the needed x
/// and y ranges. `out` then holds the same values as the full transform in the needed cells
/// (each line is transformed alone, the same way), partial values elsewhere. For windowed
/// recomputation (core/map/signed_distance_window.h).
void SquaredDistanceToOtherPhaseAt(const std::uint8_t* cells, const Eigen::Vector3i& dims,
                                   const Eigen::Vector3i& needed_begin,
                                   const Eigen::Vector3i& needed_end, float* out,
                                   EdtWorkspace* workspace);

}  // namespace topay
