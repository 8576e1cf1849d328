#include "tb/gcode/program_file.h"

#include <fstream>

#include "tb/base/args.h"
#include "tb/gcode/canon_reader.h"
#include "tb/gcode/ngc_reader.h"

namespace hwinterp::gcode {

namespace {

// The stream, then the reader that reads it (members are built in order).
template <class Reader>
class FileSource : public MoveSource {
 public:
  explicit FileSource(const std::string& path) : in_(open(path)), reader_(in_, path) {}
  bool next(Move& m) override { return reader_.next(m); }
  const ReaderStats& stats() const override { return reader_.stats(); }

 private:
  static std::ifstream open(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw cli::UsageError("cannot open '" + path + "'");
    return in;
  }
  std::ifstream in_;
  Reader reader_;
};

}  // namespace

std::unique_ptr<MoveSource> open_ngc(const std::string& path) {
  return std::make_unique<FileSource<NgcReader>>(path);
}

std::unique_ptr<MoveSource> open_canon(const std::string& path) {
  return std::make_unique<FileSource<CanonReader>>(path);
}

}  // namespace hwinterp::gcode
