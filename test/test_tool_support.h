// Helpers of the swn tool's end-to-end tests (test_tool*.cpp): running the tool, reading its outputs.
#ifndef SWN_TEST_TOOL_SUPPORT_H
#define SWN_TEST_TOOL_SUPPORT_H

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace tool_test {

const std::string tool = SWN_TOOL_PATH;
const std::string demo = std::string(SWN_REPO_DATA_DIR) + "/swn-demo/";
const std::string corpus = std::string(SWN_TEST_DATA_DIR) + "/malformed/";

struct Tool_run
{
  int status = -1;
  std::string out, err;
};

inline std::string slurp(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// runs the tool (or `program`) with `args`; `env` (for instance "env -u X Y=1") goes before it on the
// command line
inline Tool_run run(const std::string& args, const std::string& env = std::string(), const std::string& program = tool)
{
  static int counter = 0;
  const fs::path tmp = fs::temp_directory_path() / ("swn_tool_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  const std::string cmd = env + " '" + program + "' " + args + " >'" + tmp.string() + ".out' 2>'" + tmp.string() + ".err'";
  const int raw = std::system(cmd.c_str());
  Tool_run r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(tmp.string() + ".out");
  r.err = slurp(tmp.string() + ".err");
  fs::remove(tmp.string() + ".out");
  fs::remove(tmp.string() + ".err");
  return r;
}

inline fs::path fresh_dir(const std::string& name)
{
  const fs::path d = fs::temp_directory_path() / ("swn_tool_out_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  return d;
}

inline std::vector<int> read_labels(const fs::path& file)
{
  std::ifstream in(file);
  std::vector<int> l;
  int x;
  while(in >> x) l.push_back(x);
  return l;
}

inline std::map<int, int> histogram(const std::vector<int>& labels)
{
  std::map<int, int> h;
  for(int l : labels) ++h[l];
  return h;
}

// Runs a demo case and returns the label histogram; checks every output file exists.
inline std::map<int, int> solve_demo(const std::string& args, const std::string& name, std::string* summary = nullptr)
{
  const fs::path out = fresh_dir(name);
  const Tool_run r = run(args + " --quiet --output-dir '" + out.string() + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  for(const char* f : {"labels.txt", "mesh.ply", "w.obj", "bounding.obj", "nonbounding.obj", "completed.obj", "summary.json"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  EXPECT_TRUE(r.out.empty()) << "--quiet printed: " << r.out;
  if(summary) *summary = slurp((out / "summary.json").string());
  const std::map<int, int> h = histogram(read_labels(out / "labels.txt"));
  fs::remove_all(out);
  return h;
}

// the number after "KEY": in `json` (the first one at or after `from`); -1 if none
inline double json_number(const std::string& json, const std::string& key, std::size_t from = 0)
{
  std::smatch m;
  const std::regex number("\"" + key + "\":\\s*(-?[0-9.eE+]+)");
  const std::string tail = json.substr(std::min(from, json.size()));
  return std::regex_search(tail, m, number) ? std::stod(m[1]) : -1;
}

inline int chain_edges_in_obj(const std::string& text)
{
  // count the segments of the `l` polylines
  std::istringstream in(text);
  std::string line;
  int segments = 0;
  while(std::getline(in, line))
    if(line.rfind("l ", 0) == 0)
    {
      std::istringstream ls(line.substr(2));
      int k, n = 0;
      while(ls >> k) ++n;
      segments += n - 1;
    }
  return segments;
}

} // namespace tool_test

using namespace tool_test;

#endif
