// An RGBA8 image in memory (row 0 at the top) and PNG output.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace jelly::render {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  ///< width·height·4 bytes, row 0 is the top row

  bool empty() const { return width <= 0 || height <= 0; }
  /// Pixel (x, y), y counted from the top. Requires 0 ≤ x < width, 0 ≤ y < height.
  std::array<std::uint8_t, 4> at(int x, int y) const {
    const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 4;
    return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
  }
};

/// Writes `image` as a PNG; creates missing parent folders. Returns "" or the error (with path).
std::string write_png(const std::filesystem::path& path, const Image& image);

/// The w×h rectangle of `src` at (x, y) (top-left), clipped to src.
Image crop(const Image& src, int x, int y, int w, int h);

/// Copies `src` into `dst` at (x, y) (top-left), clipped to dst.
void blit(const Image& src, Image& dst, int x, int y);

}  // namespace jelly::render
