#include "tb/report/step_times.h"

#include <stdexcept>

#include "models/common.h"

namespace hwinterp::tb {

namespace {
constexpr const char* kLetters = models::kAxisLetters;
constexpr int kMaxAxes = 6;
}  // namespace

StepTimesCsv::StepTimesCsv(const std::string& path, int axes) : path_(path), axes_(axes) {
  if (axes < 1 || axes > kMaxAxes)
    throw std::runtime_error("step times: " + std::to_string(axes) +
                             " axes, at most 6 have letters");
  out_.open(path);
  if (!out_) throw std::runtime_error("cannot write step times '" + path + "'");
  out_ << "clock,axis,dir\n";
}

void StepTimesCsv::row(uint64_t clock, int axis, bool negative) {
  out_ << clock << ',' << kLetters[axis] << (negative ? ",-1\n" : ",1\n");
}

void StepTimesCsv::close() {
  out_.close();
  if (!out_) throw std::runtime_error("error writing step times '" + path_ + "'");
}

}  // namespace hwinterp::tb
