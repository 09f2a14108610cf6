// swn_fuzz_driver: a deterministic mutation fuzzer of the swn tool's readers, for ctest and for
// compilers without libFuzzer.
//
//   swn_fuzz_driver --grid GRID.off [--seed S] [--runs N] [--seconds T] CORPUS_DIR...
//
// Reads every corpus file whose format is known from its name's ending (.obj .off .ply .stl, .txt: a curve
// file on GRID; .polylines.obj, .svg: curves off the mesh on a unit grid; .soup.obj: the soup route;
// .offmesh.obj: a mesh with a fixed stroke and drawing; see fuzz_readers.h), checks it, then mutates the files round robin with a fixed-seed generator (bit flips,
// bytes and tokens replaced, inserted, deleted, duplicated; lines spliced from another file of the same
// format) until N runs or T seconds; files over 4 KB are read once, not mutated. Every input must be read or refused with an Input_error: another
// exception is reported with the run number and the input is written to swn-fuzz-failure.FORMAT; a crash
// writes it to swn-fuzz-crash.FORMAT first. The same seed gives the same sequence of inputs (a time limit
// only cuts it short). Prints the counts per format; exit status 0 when nothing failed.

#include "fuzz_readers.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

struct Seed { std::string format, name, data; };
const std::size_t max_mutated_size = 4096;

// The input being read, for the crash handler (written with write(): async-signal-safe).
const char* current_data = nullptr;
std::size_t current_size = 0;
char crash_file[64] = "swn-fuzz-crash.bin";

extern "C" void write_input_and_reraise(int sig)
{
  const int fd = ::open(crash_file, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if(fd >= 0 && current_data)
  {
    if(::write(fd, current_data, current_size) < 0) {}
    ::close(fd);
  }
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

// tokens that reach the readers' edge cases: extreme integers and reals, keywords, separators
const std::string interesting[] = {
  "0", "-1", "1", "2", "3", "255", "256", "65536", "4294967295", "4294967296", "2147483648",
  "9223372036854775807", "-9223372036854775808", "18446744073709551616", "1e308", "-1e308", "1e-320",
  "nan", "inf", "-inf", "0.5", "1e160", "1e-160", " ", "\n", "\r\n", "\t", "#", "#offset ", "#offset -1\n",
  "/", "//", "v ", "f ", "l ", "e ", "c ", "h ", "vt ", "element ", "property ", "list ", "uchar ", "int ",
  "float ", "double ", "end_header\n", "format binary_little_endian 1.0\n", "format ascii 1.0\n", "solid ",
  "facet normal 0 0 0\n", "vertex ", "endloop\n", "endfacet\n", "endsolid\n", "OFF\n", "# swn polylines\n",
  "# swn halfedges\n", "\xEF\xBB\xBF", std::string(1, '\0'), "<svg>", "<path d=\"", "\"/>", "<polygon points=\"",
  "<line x1=\"", "M ", "m ", "L ", "l ", "H ", "V ", "Z", "z", ",", "'", "\"", "<!--", "-->", ">", "<"};

class Mutator
{
public:
  explicit Mutator(std::uint64_t seed) : rng_(seed) {}

  std::size_t below(std::size_t n) { return n == 0 ? 0 : std::size_t(rng_() % n); }

  // 1 to 4 mutations of `s`; `other` (a file of the same format) feeds the splices
  void mutate(std::string& s, const std::string& other)
  {
    const std::size_t count = 1 + below(4);
    for(std::size_t k = 0; k < count; ++k)
    {
      const std::size_t pos = below(s.size() + 1);
      switch(below(8))
      {
        case 0: if(!s.empty()) s[below(s.size())] ^= char(1u << below(8)); break;                 // bit flip
        case 1: if(!s.empty()) s[below(s.size())] = char(below(256)); break;                       // byte
        case 2: s.insert(pos, interesting_token()); break;                                          // token in
        case 3: s.erase(pos, below(16)); break;                                                     // delete
        case 4: { const std::size_t n = below(64); s.insert(pos, s.substr(pos, n)); break; }       // duplicate
        case 5: replace_number(s); break;                                                           // number
        case 6: if(!other.empty()) { const std::size_t a = below(other.size()); s.insert(pos, other.substr(a, below(256))); } break;
        default: swap_lines(s); break;
      }
      if(s.size() > (1u << 20)) s.resize(1u << 20);
    }
  }

private:
  const std::string& interesting_token() { return interesting[below(sizeof(interesting) / sizeof(interesting[0]))]; }

  // replaces a run of digits by an interesting token
  void replace_number(std::string& s)
  {
    if(s.empty()) return;
    std::size_t p = below(s.size());
    while(p < s.size() && !(s[p] >= '0' && s[p] <= '9')) ++p;
    if(p == s.size()) return;
    std::size_t e = p;
    while(e < s.size() && ((s[e] >= '0' && s[e] <= '9') || s[e] == '.' || s[e] == '-' || s[e] == 'e')) ++e;
    s.replace(p, e - p, interesting_token());
  }

  void swap_lines(std::string& s)
  {
    std::vector<std::string> lines;
    std::istringstream in(s);
    for(std::string l; std::getline(in, l);) lines.push_back(l);
    if(lines.size() < 2) return;
    std::swap(lines[below(lines.size())], lines[below(lines.size())]);
    s.clear();
    for(const std::string& l : lines) s += l + "\n";
  }

  std::mt19937_64 rng_;
};

int usage(const std::string& error)
{
  std::cerr << "swn_fuzz_driver: " << error << "\n"
            << "usage: swn_fuzz_driver --grid GRID.off [--seed S] [--runs N] [--seconds T] CORPUS_DIR...\n";
  return 2;
}

} // namespace

int main(int argc, char** argv)
{
  std::string grid_path;
  std::uint64_t seed = 33;
  std::size_t max_runs = 100000;
  double seconds = 5;
  std::vector<std::string> dirs;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&]() -> std::string { return i + 1 < argc ? argv[++i] : std::string(); };
    if(a == "--grid") grid_path = value();
    else if(a == "--seed") seed = std::strtoull(value().c_str(), nullptr, 10);
    else if(a == "--runs") max_runs = std::strtoull(value().c_str(), nullptr, 10);
    else if(a == "--seconds") seconds = std::strtod(value().c_str(), nullptr);
    else if(!a.empty() && a[0] == '-') return usage("unknown option " + a);
    else dirs.push_back(a);
  }
  if(grid_path.empty() || dirs.empty()) return usage("a grid mesh and at least one corpus directory are needed");

  std::vector<Seed> corpus;
  for(const std::string& d : dirs)
  {
    std::vector<fs::path> files;
    for(const auto& e : fs::directory_iterator(d))
      if(e.is_regular_file() && !swn_fuzz::format_of(e.path().string()).empty()) files.push_back(e.path());
    std::sort(files.begin(), files.end());   // the directory order is not deterministic
    for(const fs::path& p : files)
    {
      std::ifstream in(p, std::ios::binary);
      std::stringstream ss;
      ss << in.rdbuf();
      corpus.push_back(Seed{swn_fuzz::format_of(p.string()), p.filename().string(), ss.str()});
    }
  }
  std::vector<std::size_t> small;   // the seeds that are mutated
  for(std::size_t k = 0; k < corpus.size(); ++k) if(corpus[k].data.size() <= max_mutated_size) small.push_back(k);
  if(small.empty()) return usage("no corpus file with a known extension and at most 4 KB");
  const auto meshes = swn_fuzz::fixed_meshes(grid_path);
  for(int sig : {SIGSEGV, SIGABRT, SIGFPE, SIGBUS, SIGILL}) std::signal(sig, write_input_and_reraise);
  std::ostringstream quiet;   // CGAL's binary readers print their complaints on std::cerr: kept out
  std::cerr.rdbuf(quiet.rdbuf());

  struct Counts { std::size_t runs = 0, read = 0, refused = 0; };
  std::map<std::string, Counts> counts;
  Mutator mutator(seed);
  const auto t0 = std::chrono::steady_clock::now();
  std::size_t run = 0, failures = 0;
  for(; run < max_runs; ++run)
  {
    if(run % 64 == 0 && std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > seconds) break;
    // the seeds themselves first, then mutants of the small ones (a few KB: many runs per second), round robin
    const bool seed_run = run < corpus.size();
    const Seed& s = seed_run ? corpus[run] : corpus[small[(run - corpus.size()) % small.size()]];
    std::string input = s.data;
    if(!seed_run)
    {
      std::vector<std::size_t> same;
      for(std::size_t k : small) if(corpus[k].format == s.format) same.push_back(k);
      mutator.mutate(input, corpus[same[mutator.below(same.size())]].data);
    }
    std::snprintf(crash_file, sizeof(crash_file), "swn-fuzz-crash.%s", swn_fuzz::extension_of(s.format).c_str());
    current_data = input.data();
    current_size = input.size();
    Counts& c = counts[s.format];
    ++c.runs;
    try
    {
      (swn_fuzz::read_input(input, s.format, *meshes) == swn_fuzz::Outcome::READ ? c.read : c.refused)++;
    }
    catch(const std::exception& e)
    {
      ++failures;
      const std::string file = "swn-fuzz-failure." + swn_fuzz::extension_of(s.format);
      std::ofstream(file, std::ios::binary) << input;
      std::cout << "FAILURE: run " << run << " (seed " << seed << ", mutant of " << s.name << "): " << e.what()
                << " (not an Input_error; input written to " << file << ")\n";
    }
  }
  current_data = nullptr;
  std::cerr.rdbuf(std::cout.rdbuf());
  std::size_t total_read = 0, total_refused = 0;
  for(const auto& kv : counts)
  {
    std::cout << kv.first << ": " << kv.second.runs << " runs, " << kv.second.read << " read, " << kv.second.refused
              << " refused with an Input_error\n";
    total_read += kv.second.read;
    total_refused += kv.second.refused;
  }
  std::cout << "total: " << run << " runs (seed " << seed << ", " << corpus.size() << " corpus files), " << total_read
            << " read, " << total_refused << " refused, " << failures << " failures, "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s\n";
  return failures == 0 ? 0 : 1;
}
