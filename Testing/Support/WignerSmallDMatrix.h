// The whole Wigner small-d matrix of one band (conventions in WignerD.h), for the tests
// that check the recursions against it.
#ifndef mobius_WignerSmallDMatrix_h
#define mobius_WignerSmallDMatrix_h

#include <Eigen/Core>

namespace mobius
{
/// The full matrix d^l(β), (2l+1) x (2l+1), entry (m+l, n+l), via the Δ factorization
/// (O(l^3)).
Eigen::MatrixXd WignerSmallDMatrix(int l, double beta);
}

#endif
