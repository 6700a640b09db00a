// The fuzz targets' driver outside libFuzzer (every build, ctest "fuzz.<name>"): runs
// LLVMFuzzerTestOneInput on every file of the given files and folders (the committed seeds and
// regressions), then on `--mutations N` random mutations of them (bit flips, byte values,
// insertions, erasures, duplications, splices, truncations; fixed --seed, so a run repeats).
// Before each mutated input runs it is written to --last-input, so a crash leaves the input
// that caused it. Exits 1 when no input was found; a crash or a failed check aborts.
//
//   <name>_fuzz_replay [--mutations N] [--seed S] [--last-input FILE] PATH...
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
extern "C" __attribute__((weak)) int LLVMFuzzerInitialize(int* argc, char*** argv);

namespace {

using Bytes = std::vector<std::uint8_t>;
namespace fs = std::filesystem;

Bytes ReadFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Every regular file under `path` (or `path` itself), sorted for a stable order.
std::vector<fs::path> FilesUnder(const fs::path& path) {
  std::vector<fs::path> files;
  if (fs::is_regular_file(path)) return {path};
  if (!fs::is_directory(path)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(path)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

void RunOne(const Bytes& input) {
  // A copy of exactly the input's size, so reads past its end are reads past an allocation.
  std::vector<std::uint8_t> copy(input);
  LLVMFuzzerTestOneInput(copy.empty() ? nullptr : copy.data(), copy.size());
}

// One random edit of `input` (another input may be spliced in).
void MutateOnce(std::mt19937_64& rng, const std::vector<Bytes>& pool, Bytes* input) {
  auto index = [&rng](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
  static constexpr std::uint8_t kInteresting[] = {0x00, 0x01, 0x7f, 0x80, 0xff, 0xfe, 0x40, 0x10};
  Bytes& b = *input;
  switch (index(8)) {
    case 0:  // flip a bit
      if (!b.empty()) b[index(b.size())] ^= static_cast<std::uint8_t>(1u << index(8));
      break;
    case 1:  // a random byte
      if (!b.empty()) b[index(b.size())] = static_cast<std::uint8_t>(rng());
      break;
    case 2:  // an interesting byte value
      if (!b.empty()) b[index(b.size())] = kInteresting[index(std::size(kInteresting))];
      break;
    case 3: {  // insert 1-8 random bytes
      const std::size_t at = index(b.size() + 1);
      const std::size_t n = 1 + index(8);
      for (std::size_t i = 0; i < n; ++i) b.insert(b.begin() + static_cast<long>(at), static_cast<std::uint8_t>(rng()));
      break;
    }
    case 4:  // erase a range
      if (!b.empty()) {
        const std::size_t at = index(b.size());
        const std::size_t n = 1 + index(std::min<std::size_t>(16, b.size() - at));
        b.erase(b.begin() + static_cast<long>(at), b.begin() + static_cast<long>(at + n));
      }
      break;
    case 5:  // duplicate a range
      if (!b.empty()) {
        const std::size_t at = index(b.size());
        const std::size_t n = 1 + index(std::min<std::size_t>(32, b.size() - at));
        const Bytes chunk(b.begin() + static_cast<long>(at), b.begin() + static_cast<long>(at + n));
        b.insert(b.begin() + static_cast<long>(index(b.size() + 1)), chunk.begin(), chunk.end());
      }
      break;
    case 6: {  // splice: our head, another input's tail
      const Bytes& other = pool[index(pool.size())];
      const std::size_t keep = index(b.size() + 1);
      const std::size_t from = index(other.size() + 1);
      b.resize(keep);
      b.insert(b.end(), other.begin() + static_cast<long>(from), other.end());
      break;
    }
    default:  // truncate
      b.resize(index(b.size() + 1));
      break;
  }
}

}  // namespace

int main(int argc, char** argv) {
  long mutations = 0;
  unsigned long long seed = 1;
  std::string last_input;
  std::vector<fs::path> paths;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--mutations" && i + 1 < argc) {
      mutations = std::atol(argv[++i]);
    } else if (arg == "--seed" && i + 1 < argc) {
      seed = std::strtoull(argv[++i], nullptr, 10);
    } else if (arg == "--last-input" && i + 1 < argc) {
      last_input = argv[++i];
    } else {
      paths.emplace_back(arg);
    }
  }
  if (LLVMFuzzerInitialize != nullptr) LLVMFuzzerInitialize(&argc, &argv);

  std::vector<Bytes> pool;
  for (const fs::path& path : paths) {
    const std::vector<fs::path> files = FilesUnder(path);
    std::cout << path.string() << ": " << files.size() << " input(s)\n";
    for (const fs::path& file : files) {
      pool.push_back(ReadFile(file));
      RunOne(pool.back());
    }
  }
  if (pool.empty()) {
    std::cerr << "fuzz replay: no input found in the given paths (the seed corpus is missing)\n";
    return 1;
  }
  if (!last_input.empty()) fs::create_directories(fs::path(last_input).parent_path());
  std::mt19937_64 rng(seed);
  for (long i = 0; i < mutations; ++i) {
    Bytes input = pool[std::uniform_int_distribution<std::size_t>(0, pool.size() - 1)(rng)];
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int k = 0; k < edits; ++k) MutateOnce(rng, pool, &input);
    if (!last_input.empty()) {
      std::ofstream(last_input, std::ios::binary).write(reinterpret_cast<const char*>(input.data()),
                                                         static_cast<std::streamsize>(input.size()));
    }
    RunOne(input);
  }
  std::cout << "fuzz replay: " << pool.size() << " seed/regression input(s) and " << mutations
            << " mutation(s) (seed " << seed << ") ran without a failure\n";
  return 0;
}
