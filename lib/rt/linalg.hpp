// Small dense and banded linear algebra for the discrete-ordinate solver (no LAPACK).
// Matrices are row-major std::vector<double> unless stated; all routines are
// allocation-free when given their work arrays, so the solver can reuse buffers.
#pragma once

#include <cstddef>
#include <vector>

namespace sigchain::rt::linalg {

// Cholesky factor of a symmetric positive-definite n x n matrix a (row-major): on
// return the lower triangle of a holds L with a = L L^T. Returns false when a is not
// positive definite (a pivot <= 0).
bool cholesky(double* a, int n);

// Eigen-decomposition of a symmetric n x n matrix (n <= 128): Householder
// tridiagonalisation and implicit QR with Wilkinson shifts. a is destroyed; eigenvalues go to
// eval[n], eigenvectors to the columns of v (row-major n x n: v[i * n + j] is component i of vector
// j).
void symmetric_eigen(double* a, int n, double* eval, double* v);

// Dense LU with partial pivoting of a row-major n x n matrix in place; returns false
// when singular. solve_lu overwrites b with the solution.
bool lu_factor(double* a, int n, int* piv);
void lu_solve(const double* a, int n, const int* piv, double* b);
// The same for the ncol right-hand sides in the columns of the row-major n x ncol b.
void lu_solve_columns(const double* a, int n, const int* piv, double* b, int ncol);

// Banded matrix with kl sub- and ku super-diagonals, factored by LU with partial
// pivoting (the method of LINPACK/LAPACK gbtrf, written here from the algorithm).
class BandMatrix {
public:
    void reset(int n, int kl, int ku);  // zeroes the matrix, keeping its storage
    double& at(int row, int col) { return m_ab[index(row, col)]; }
    int size() const { return m_n; }
    bool factor();                // false when singular
    void solve(double* b) const;  // after factor(): overwrites b with the solution

private:
    std::size_t index(int row, int col) const {
        return static_cast<std::size_t>(col) * m_ld + (m_kv + row - col);
    }
    int m_n = 0, m_kl = 0, m_ku = 0, m_kv = 0, m_ld = 0;
    std::vector<double> m_ab;  // column-major band storage, ld = 2 kl + ku + 1
    std::vector<int> m_piv;
    std::vector<int> m_km;  // rows eliminated below each pivot
};

}  // namespace sigchain::rt::linalg
