// The one instantiation of Eigen::JacobiSVD<Eigen::MatrixXd> that files including
// jelly/skeleton/svd.hpp link with (A4's least-squares solve).
#include "jelly/skeleton/svd.hpp"

template class Eigen::JacobiSVD<Eigen::MatrixXd>;
