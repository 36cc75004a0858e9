#pragma once
// Deflation space of the finest level's conjugate gradients (internal to the renderer; see
// docs/rendering.md). The V-cycle corrects badly the error of a region that reaches the rest of
// the image only through a neck of one or two pixels (a pocket between two curves) or a long
// channel: the error there is nearly constant over the region, or varies slowly along the
// channel, and P, which follows the links, represents neither on the coarse levels. CG spent
// about one iteration per factor of three on such modes (the ladybug's leg pockets). So the
// piecewise constants of "pieces" are deflated exactly (A-DEF2: Tang, Nabben, Vuik and Erlangga
// 2009): the free pixels split where necks up to two pixels wide are cut, and further into
// kTileSize squares; Z holds one indicator vector per piece, and every CG direction is made
// A-orthogonal to them with one small sparse solve E c = Z^T A z, E = Z^T A Z (A Z is 0 except
// at the pixels with a link leaving their piece, so Z^T A z is cheap). The solver may also name
// pixels that are pieces of one pixel each (where the V-cycle corrects slowest): Z then spans
// every function there, and E holds A's own rows for them.

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cstdint>
#include <vector>

#include "multigrid_levels.hpp"

namespace vicc_glyphs::multigrid_detail {

class DeflationSpace {
 public:
  /// Labels the pieces of `fine` and factorises E (reusing the memory of the last build).
  /// Each free pixel listed in `singletons` (fine indices) is a piece of its own.
  void build(const FineLevel& fine, const std::vector<int>& singletons = {});

  /// Regions (columns of Z); 0 when there is nothing to deflate.
  int count() const { return count_; }
  /// Per fine index the region of a free pixel; count() at Dirichlet pixels and in the ghost
  /// border (whose entry of every coarse vector is 0).
  const std::uint32_t* labels() const { return labels_.data(); }
  /// The free pixels with a link that leaves their region (to another one or to a Dirichlet
  /// pixel): the only rows where A Z is not 0.
  const std::vector<int>& boundary() const { return boundary_; }
  /// Solves E c = g in place, one column per channel.
  void solve(Eigen::MatrixXd& g) const {
    const Eigen::MatrixXd solution = factor_.solve(g);
    g = solution;
  }

 private:
  // Side of the squares the regions are split into: joinPieces joins no link across their edges.
  static constexpr int kTileSize = 128;
  // interior_: kInterior, kSingleton (a piece of its own, joins nothing) or 0.
  static constexpr std::uint8_t kInterior = 1, kSingleton = 2;

  void markInterior(const FineLevel& fine, const std::vector<int>& singletons);
  void joinPieces(const FineLevel& fine);
  bool hasInteriorLink(const FineLevel& fine, int q) const;
  void compactLabels(const FineLevel& fine);
  int find(int p) {
    while (parent_[p] != p) {
      parent_[p] = parent_[parent_[p]];  // path halving
      p = parent_[p];
    }
    return p;
  }
  void unite(int p, int q) {
    const int a = find(p), b = find(q);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }
  void factorise(const FineLevel& fine);

  int count_ = 0;
  std::vector<std::uint8_t> interior_;
  std::vector<int> parent_;
  std::vector<std::uint8_t> left_joined_;  // joinPieces' row above
  std::vector<double> diagonal_;
  std::vector<std::uint32_t> labels_;
  std::vector<int> boundary_;
  std::vector<Eigen::Triplet<double>> triplets_;
  Eigen::SparseMatrix<double> coarse_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor_;
};

}  // namespace vicc_glyphs::multigrid_detail
