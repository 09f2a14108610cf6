// The swn tool on hostile input and interrupted runs (issue 33): files that are not regular files,
// meshes in extreme units, and SIGTERM / SIGINT while the outputs are written. The malformed-input corpus
// (test/data/malformed, run by Tool.MalformedCorpusGivesFileLineAndExitCode2) holds the other cases.
#include "test_tool_support.h"

#include <signal.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <sstream>
#include <thread>

namespace {

// the temporaries of an interrupted Atomic_output_dir in `dir`
std::size_t temporaries_in(const fs::path& dir)
{
  std::size_t n = 0;
  std::error_code ec;
  for(fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    n += it->path().filename().string().find(".swn-tmp-") != std::string::npos;
  return n;
}

} // namespace

// Devices and FIFOs are refused at once (before: /dev/zero grew without bound, a FIFO blocked forever);
// `timeout` turns a regression into a failure instead of a hang.
TEST(ToolHostile, NonRegularInputsAreRefused)
{
  const fs::path d = fresh_dir("nonregular");
  fs::create_directories(d);
  fs::create_symlink("/dev/zero", d / "zero.obj");
  ASSERT_EQ(::mkfifo((d / "fifo.off").c_str(), 0600), 0);
  ASSERT_EQ(::mkfifo((d / "fifo.txt").c_str(), 0600), 0);
  const std::string out = (d / "out").string();
  for(const std::string& args : {"'" + (d / "zero.obj").string() + "'", "'" + (d / "fifo.off").string() + "'",
                                 "'" + demo + "torus.obj' --curve /dev/zero",
                                 "'" + demo + "torus.obj' --curve '" + (d / "fifo.txt").string() + "'"})
  {
    const Tool_run r = run(args + " --output-dir '" + out + "'", "timeout 60");
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find("is not a regular file"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
  fs::remove_all(d);
}

// Every quantity of the method is scale invariant: the torus and its curve at 1e160 and 1e-160 (whose
// areas overflow, resp. underflow, in the unit of the file) give the labels and G of the unit torus.
TEST(ToolHostile, ExtremeUnitsGiveTheUnitLabels)
{
  const std::string args = " --curve '" + demo + "torus-phi.txt' --quiet --output-dir ";
  const fs::path ref = fresh_dir("units_ref");
  ASSERT_EQ(run("'" + demo + "torus.obj'" + args + "'" + ref.string() + "'").status, 0);
  const std::vector<int> labels = read_labels(ref / "labels.txt");
  const int G = chain_edges_in_obj(slurp((ref / "nonbounding.obj").string()));
  EXPECT_EQ(G, 78);   // the completed meridian
  for(const char* scale : {"1e160", "1e-160"})
  {
    const fs::path d = fresh_dir(std::string("units_") + scale);
    fs::create_directories(d);
    std::ifstream in(demo + "torus.obj");
    std::ofstream obj(d / "torus.obj");
    std::string line;
    while(std::getline(in, line))
    {
      if(line.rfind("v ", 0) == 0)   // "v 1.250000 0.032632 0.000000": each number gets the exponent
      {
        std::istringstream tokens(line.substr(2));
        std::string x;
        line = "v";
        while(tokens >> x) line += " " + x + (scale + 1);   // "e160" / "e-160"
      }
      obj << line << '\n';
    }
    obj.close();
    const Tool_run r = run("'" + (d / "torus.obj").string() + "'" + args + "'" + (d / "out").string() + "'");
    ASSERT_EQ(r.status, 0) << scale << ": " << r.err;
    EXPECT_EQ(read_labels(d / "out" / "labels.txt"), labels) << scale;
    EXPECT_EQ(chain_edges_in_obj(slurp((d / "out" / "nonbounding.obj").string())), G) << scale;
    fs::remove_all(d);
  }
  fs::remove_all(ref);
}

// SIGTERM or SIGINT while the outputs are written: the tool removes its temporaries (and the directory
// it created) and ends by the signal. The parent watches the output directory and signals the tool as
// soon as a temporary appears; a run that ends before it is seen is retried.
TEST(ToolHostile, SignalWhileWritingLeavesNothing)
{
  int intercepted = 0;
  for(int attempt = 0; attempt < 12 && intercepted < 4; ++attempt)
  {
    const int sig = attempt % 2 ? SIGINT : SIGTERM;
    const fs::path out = fresh_dir("signal") / "sub";
    std::fflush(nullptr);   // nothing buffered is written twice
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if(child == 0)
    {
      std::freopen("/dev/null", "w", stdout);
      std::freopen("/dev/null", "w", stderr);
      ::execl(tool.c_str(), tool.c_str(), (demo + "DoubleTorusWithLoops.obj").c_str(), "--sequential", "--quiet",
              "--output-dir", out.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    bool seen = false;
    int status = 0;
    const auto t0 = std::chrono::steady_clock::now();
    while(std::chrono::steady_clock::now() - t0 < std::chrono::seconds(120))
    {
      if(temporaries_in(out) > 0) { seen = ::kill(child, sig) == 0; break; }
      if(::waitpid(child, &status, WNOHANG) == child) { status = -1; break; }
      std::this_thread::sleep_for(std::chrono::microseconds(100));
    }
    if(status != -1) ASSERT_EQ(::waitpid(child, &status, 0), child);
    if(seen && WIFSIGNALED(status))
    {
      ++intercepted;
      EXPECT_EQ(WTERMSIG(status), sig);
      EXPECT_EQ(temporaries_in(out), 0u);
      EXPECT_FALSE(fs::exists(out)) << "the interrupted run left its output directory";
    }
    else if(seen)
      EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0 && fs::exists(out / "summary.json"));   // ended first
    fs::remove_all(out.parent_path());
  }
  EXPECT_GE(intercepted, 1) << "no run was caught while writing";
}
