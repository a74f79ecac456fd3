// What the headless render tests share: an offscreen backend with a renderer on it, and counting
// the pixels of one material's colour in what it drew.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "jelly/render/backend.hpp"
#include "jelly/render/image.hpp"
#include "jelly/render/renderer.hpp"

namespace jelly::render {

/// An offscreen backend of w × h pixels and a renderer on it, for a fixture's SetUp:
/// `ASSERT_TRUE(open_offscreen(kW, kH, backend_, renderer_));`.
inline ::testing::AssertionResult open_offscreen(int w, int h, std::unique_ptr<Backend>& backend,
                                                 std::unique_ptr<Renderer>& renderer) {
  BackendOptions o;
  o.name = "offscreen";
  o.width = w;
  o.height = h;
  auto created = create_backend(o);
  if (!created.backend) return ::testing::AssertionFailure() << created.error;
  backend = std::move(created.backend);
  renderer = std::make_unique<Renderer>(backend->gl());
  return ::testing::AssertionSuccess();
}

/// The pixels of `img` within `radius` of `at` (everywhere: the default) whose chromaticity is
/// that of `color` after the shader's gamma (1/1.1), lit or shaded; dark pixels (r + g + b < 45)
/// do not count.
inline int pixels_of(const Image& img, const Eigen::Vector3f& color,
                     const Eigen::Vector2d& at = Eigen::Vector2d::Zero(),
                     double radius = std::numeric_limits<double>::infinity()) {
  const Eigen::Vector3d g(std::pow(color.x(), 1 / 1.1), std::pow(color.y(), 1 / 1.1),
                          std::pow(color.z(), 1 / 1.1));
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      if ((Eigen::Vector2d(x, y) - at).norm() > radius) continue;
      const auto p = img.at(x, y);
      const double sum = double(p[0]) + p[1] + p[2];
      if (sum < 45.0) continue;
      const Eigen::Vector3d c = Eigen::Vector3d(p[0], p[1], p[2]) / sum;
      n += (c - g / g.sum()).norm() < 0.05;
    }
  return n;
}

}  // namespace jelly::render
