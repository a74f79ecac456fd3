#include "jelly/render/image.hpp"

#include <algorithm>
#include <system_error>

#include <stb_image_write.h>  // implementation from libstb (Debian libstb-dev)

namespace jelly::render {

std::string write_png(const std::filesystem::path& path, const Image& image) {
  if (image.empty()) return path.string() + ": nothing to write (empty image)";
  std::error_code ec;
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ec);
  if (ec) return path.parent_path().string() + ": cannot create folder: " + ec.message();
  const int ok = stbi_write_png(path.string().c_str(), image.width, image.height, 4,
                                image.rgba.data(), image.width * 4);
  return ok ? std::string() : path.string() + ": cannot write PNG";
}

Image crop(const Image& src, int x, int y, int w, int h) {
  x = std::clamp(x, 0, src.width);
  y = std::clamp(y, 0, src.height);
  w = std::clamp(w, 0, src.width - x);
  h = std::clamp(h, 0, src.height - y);
  Image out;
  out.width = w;
  out.height = h;
  out.rgba.resize(static_cast<std::size_t>(w) * h * 4);
  for (int row = 0; row < h; ++row)
    std::copy_n(&src.rgba[(static_cast<std::size_t>(y + row) * src.width + x) * 4], w * 4,
                &out.rgba[static_cast<std::size_t>(row) * w * 4]);
  return out;
}

void blit(const Image& src, Image& dst, int x0, int y0) {
  for (int y = 0; y < src.height; ++y) {
    const int ty = y0 + y;
    if (ty < 0 || ty >= dst.height) continue;
    const int xa = std::max(0, -x0), xb = std::min(src.width, dst.width - x0);
    if (xa >= xb) continue;
    std::copy_n(&src.rgba[(static_cast<std::size_t>(y) * src.width + xa) * 4], (xb - xa) * 4,
                &dst.rgba[(static_cast<std::size_t>(ty) * dst.width + x0 + xa) * 4]);
  }
}

}  // namespace jelly::render
