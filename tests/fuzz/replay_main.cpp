// Replays fuzz inputs through a libFuzzer target's LLVMFuzzerTestOneInput in
// an ordinary (gcc) build: every file given, or every file of every
// directory given. ctest runs the committed corpus and the inputs that once
// crashed (tests/fuzz/corpus/<target>/) this way, so they stay regression
// tests on machines without clang. Exit 0 when every input returned.
#include <dirent.h>
#include <sys/stat.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

void collect(const std::string& path, std::vector<std::string>& files) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) {
    std::fprintf(stderr, "replay: no such input '%s'\n", path.c_str());
    std::exit(2);
  }
  if (!S_ISDIR(st.st_mode)) {
    files.push_back(path);
    return;
  }
  DIR* d = opendir(path.c_str());
  for (dirent* e; (e = readdir(d));)
    if (e->d_name[0] != '.') collect(path + "/" + e->d_name, files);
  closedir(d);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) collect(argv[i], files);
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(data.data()), data.size());
  }
  std::printf("replay: %zu inputs\n", files.size());
  return files.empty() ? 2 : 0;
}
