// Shared by the end-to-end tests of the swn tool (test_tool*.cpp): running the tool, its output files.
#ifndef SWN_TEST_TOOL_SUPPORT_H
#define SWN_TEST_TOOL_SUPPORT_H

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace swn_tool_test {

inline const std::string tool = SWN_TOOL_PATH;
inline const std::string tuned = SWN_TUNED_PATH;
inline const std::string demo = std::string(SWN_REPO_DATA_DIR) + "/swn-demo/";
inline const std::string corpus = std::string(SWN_TEST_DATA_DIR) + "/malformed/";

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

} // namespace swn_tool_test

#endif
