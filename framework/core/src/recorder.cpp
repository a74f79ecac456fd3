#include "jelly/recorder.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <stdexcept>

#include "jelly/fnv1a.hpp"

namespace jelly {

FrameSummary summarize(const World& w, const State& s, double t) {
  FrameSummary f;
  f.time = t;
  const Eigen::VectorXd& m = w.masses();
  double total = 0.0;
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    f.com += m[i] * s.x.col(i);
    total += m[i];
    f.max_speed = std::max(f.max_speed, s.v.col(i).norm());
  }
  if (total > 0.0) f.com /= total;
  const Energy e = w.energy(s);
  f.kinetic = e.kinetic;
  f.potential = e.gravitational;
  f.spring = e.spring;
  return f;
}

CsvWriter::CsvWriter(const std::filesystem::path& path, const std::string& header) {
  file_ = std::fopen(path.string().c_str(), "wb");
  if (!file_) {
    throw std::runtime_error("cannot open " + path.string() +
                             " for writing: " + std::strerror(errno));
  }
  buffer_ = header;
  buffer_ += '\n';
}

CsvWriter::~CsvWriter() {
  flush();
  if (file_) std::fclose(file_);
}

void CsvWriter::put(double value) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, value);
  buffer_.append(buf, r.ptr);
}

void CsvWriter::put(long value) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, value);
  buffer_.append(buf, r.ptr);
}

void CsvWriter::write_particles(long frame, double time, const State& s) {
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    put(frame);
    buffer_ += ',';
    put(time);
    buffer_ += ',';
    put(static_cast<long>(i));
    for (int d = 0; d < 3; ++d) {
      buffer_ += ',';
      put(s.x(d, i));
    }
    for (int d = 0; d < 3; ++d) {
      buffer_ += ',';
      put(s.v(d, i));
    }
    buffer_ += '\n';
  }
  if (buffer_.size() > (1u << 20)) flush();
}

void CsvWriter::write_summary(const FrameSummary& f) {
  const double values[] = {f.time,    f.com.x(),   f.com.y(), f.com.z(),
                           f.kinetic, f.potential, f.spring,  f.max_speed};
  for (std::size_t k = 0; k < 8; ++k) {
    if (k) buffer_ += ',';
    put(values[k]);
  }
  buffer_ += '\n';
  if (buffer_.size() > (1u << 20)) flush();
}

void CsvWriter::write_row(const std::vector<double>& values) {
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (k) buffer_ += ',';
    put(values[k]);
  }
  buffer_ += '\n';
  if (buffer_.size() > (1u << 20)) flush();
}

void CsvWriter::write_cells(const std::vector<std::variant<double, std::string>>& cells) {
  for (std::size_t k = 0; k < cells.size(); ++k) {
    if (k) buffer_ += ',';
    if (const double* v = std::get_if<double>(&cells[k])) {
      put(*v);
    } else {
      buffer_ += std::get<std::string>(cells[k]);
    }
  }
  buffer_ += '\n';
  if (buffer_.size() > (1u << 20)) flush();
}

void CsvWriter::flush() {
  if (file_ && !buffer_.empty()) {
    std::fwrite(buffer_.data(), 1, buffer_.size(), file_);
    std::fflush(file_);
  }
  buffer_.clear();
}

std::uint64_t state_hash(const State& s) {
  const auto bytes = [](const Vec3Array& a) {
    return static_cast<std::size_t>(a.size()) * sizeof(double);
  };
  return fnv1a(s.v.data(), bytes(s.v), fnv1a(s.x.data(), bytes(s.x)));
}

}  // namespace jelly
