// Eigen's JacobiSVD of a dynamic double matrix, compiled once in the framework (svd_instance.cpp).
// A file that includes this header before it uses Eigen::JacobiSVD<Eigen::MatrixXd> does not
// compile the SVD again: about 5 CPU-s at -O3, which was most of grading an A4 submission
// (docs/performance.md). The same code and flags, so the same bits.
#pragma once

#include <Eigen/SVD>

extern template class Eigen::JacobiSVD<Eigen::MatrixXd>;
