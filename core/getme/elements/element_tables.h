#pragma once

// Compile-time element tables of the paper (Secs. 2.1–2.2, Def. 3), each index one less than in
// the paper and nothing else changed (docs/node-orders.md).
// F (faces, eq. 1), F̄ (dual faces, eq. 2), N (node tetrahedra, eq. 9), W⁻¹ (Def. 3), edges.

#include <array>
#include <cstdint>

#include "getme/elements/element_type.h"

namespace getme {

// A face with 3 or 4 nodes; unused slots are -1.
struct FaceIndices {
  int size;
  std::array<int, 4> nodes;
};

using NodeTetIndices = std::array<int, 4>;
using EdgeIndices = std::array<int, 2>;
using Matrix3Rows = std::array<std::array<double, 3>, 3>;

template <ElementType kType>
struct ElementTable;

template <>
struct ElementTable<ElementType::kTetrahedron> {
  static constexpr int kNodes = 4;
  static constexpr std::array<FaceIndices, 4> kFaces = {
      {{3, {0, 1, 2, -1}}, {3, {0, 1, 3, -1}}, {3, {1, 2, 3, -1}}, {3, {2, 0, 3, -1}}}};
  static constexpr std::array<FaceIndices, 4> kDualFaces = {
      {{3, {0, 1, 3, -1}}, {3, {0, 2, 1, -1}}, {3, {0, 3, 2, -1}}, {3, {1, 2, 3, -1}}}};
  static constexpr std::array<NodeTetIndices, 1> kNodeTets = {{{0, 1, 2, 3}}};
  // The rotations of the regular tetrahedron that take node k to node 0: the even permutations
  // that swap two pairs (see FirstNodeSymmetry below).
  static constexpr std::array<std::array<int, 4>, 4> kSymmetryToFirst = {
      {{0, 1, 2, 3}, {1, 0, 3, 2}, {2, 3, 0, 1}, {3, 2, 1, 0}}};
  static constexpr std::array<EdgeIndices, 6> kEdges = {
      {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}}};
  // W⁻¹ for W columns (1,0,0) (1/2,√3/2,0) (1/2,√3/6,√(2/3)).
  static constexpr Matrix3Rows kTargetInverse = {{{1.0, -0.5773502691896258, -0.40824829046386296},
                                                  {0.0, 1.1547005383792517, -0.408248290463863},
                                                  {0.0, 0.0, 1.224744871391589}}};
};

template <>
struct ElementTable<ElementType::kHexahedron> {
  static constexpr int kNodes = 8;
  static constexpr std::array<FaceIndices, 6> kFaces = {{{4, {0, 1, 2, 3}},
                                                         {4, {0, 1, 5, 4}},
                                                         {4, {1, 2, 6, 5}},
                                                         {4, {2, 3, 7, 6}},
                                                         {4, {3, 0, 4, 7}},
                                                         {4, {4, 7, 6, 5}}}};
  static constexpr std::array<FaceIndices, 8> kDualFaces = {{{3, {0, 1, 4, -1}},
                                                             {3, {0, 2, 1, -1}},
                                                             {3, {0, 3, 2, -1}},
                                                             {3, {0, 4, 3, -1}},
                                                             {3, {5, 4, 1, -1}},
                                                             {3, {5, 1, 2, -1}},
                                                             {3, {5, 2, 3, -1}},
                                                             {3, {5, 3, 4, -1}}}};
  static constexpr std::array<NodeTetIndices, 8> kNodeTets = {{{0, 3, 4, 1},
                                                               {1, 0, 5, 2},
                                                               {2, 1, 6, 3},
                                                               {3, 2, 7, 0},
                                                               {4, 7, 5, 0},
                                                               {5, 4, 6, 1},
                                                               {6, 5, 7, 2},
                                                               {7, 6, 4, 3}}};
  // Rotations of the cube taking node k to node 0 (see FirstNodeSymmetry below): each maps a
  // node tetrahedron onto another with its three edges turned cyclically.
  static constexpr std::array<std::array<int, 8>, 8> kSymmetryToFirst = {
      {{0, 1, 2, 3, 4, 5, 6, 7},
       {1, 0, 4, 5, 2, 3, 7, 6},
       {2, 3, 0, 1, 6, 7, 4, 5},
       {3, 2, 6, 7, 0, 1, 5, 4},
       {4, 5, 1, 0, 7, 6, 2, 3},
       {5, 4, 7, 6, 1, 0, 3, 2},
       {6, 7, 3, 2, 5, 4, 0, 1},
       {7, 6, 5, 4, 3, 2, 1, 0}}};
  static constexpr std::array<EdgeIndices, 12> kEdges = {{{0, 1},
                                                          {1, 2},
                                                          {2, 3},
                                                          {3, 0},
                                                          {4, 5},
                                                          {5, 6},
                                                          {6, 7},
                                                          {7, 4},
                                                          {0, 4},
                                                          {1, 5},
                                                          {2, 6},
                                                          {3, 7}}};
  static constexpr Matrix3Rows kTargetInverse = {
      {{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}};
};

template <>
struct ElementTable<ElementType::kPyramid> {
  static constexpr int kNodes = 5;
  static constexpr std::array<FaceIndices, 5> kFaces = {{{4, {0, 1, 2, 3}},
                                                         {3, {0, 1, 4, -1}},
                                                         {3, {1, 2, 4, -1}},
                                                         {3, {2, 3, 4, -1}},
                                                         {3, {3, 0, 4, -1}}}};
  static constexpr std::array<FaceIndices, 5> kDualFaces = {{{3, {0, 1, 4, -1}},
                                                             {3, {0, 2, 1, -1}},
                                                             {3, {0, 3, 2, -1}},
                                                             {3, {0, 4, 3, -1}},
                                                             {4, {1, 2, 3, 4}}}};
  // The apex has four edges and no node tetrahedron (paper, after eq. 9).
  static constexpr std::array<NodeTetIndices, 4> kNodeTets = {
      {{0, 1, 3, 4}, {1, 2, 0, 4}, {2, 3, 1, 4}, {3, 0, 2, 4}}};
  static constexpr std::array<EdgeIndices, 8> kEdges = {
      {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 4}, {2, 4}, {3, 4}}};
  // W⁻¹ for W columns (1,0,0) (0,1,0) (1/2,1/2,√2/2).
  static constexpr Matrix3Rows kTargetInverse = {{{1.0, 0.0, -0.7071067811865475},
                                                  {0.0, 1.0, -0.7071067811865475},
                                                  {0.0, 0.0, 1.414213562373095}}};
};

template <>
struct ElementTable<ElementType::kPrism> {
  static constexpr int kNodes = 6;
  static constexpr std::array<FaceIndices, 5> kFaces = {{{3, {0, 1, 2, -1}},
                                                         {4, {0, 1, 4, 3}},
                                                         {4, {1, 2, 5, 4}},
                                                         {4, {2, 0, 3, 5}},
                                                         {3, {3, 5, 4, -1}}}};
  static constexpr std::array<FaceIndices, 6> kDualFaces = {{{3, {0, 1, 3, -1}},
                                                             {3, {0, 2, 1, -1}},
                                                             {3, {0, 3, 2, -1}},
                                                             {3, {4, 3, 1, -1}},
                                                             {3, {4, 1, 2, -1}},
                                                             {3, {4, 2, 3, -1}}}};
  static constexpr std::array<NodeTetIndices, 6> kNodeTets = {
      {{0, 1, 2, 3}, {1, 2, 0, 4}, {2, 0, 1, 5}, {3, 5, 4, 0}, {4, 3, 5, 1}, {5, 4, 3, 2}}};
  // Rotations of the regular prism taking node k to node 0 (see FirstNodeSymmetry below): the
  // turns about its axis, and the half turns about a horizontal axis that swap its triangles.
  // Each maps every node tetrahedron onto one of the table's, position for position.
  static constexpr std::array<std::array<int, 6>, 6> kSymmetryToFirst = {{{0, 1, 2, 3, 4, 5},
                                                                          {1, 2, 0, 4, 5, 3},
                                                                          {2, 0, 1, 5, 3, 4},
                                                                          {3, 5, 4, 0, 2, 1},
                                                                          {4, 3, 5, 1, 0, 2},
                                                                          {5, 4, 3, 2, 1, 0}}};
  static constexpr std::array<EdgeIndices, 9> kEdges = {
      {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}, {0, 3}, {1, 4}, {2, 5}}};
  // W⁻¹ for W columns (1,0,0) (1/2,√3/2,0) (0,0,1).
  static constexpr Matrix3Rows kTargetInverse = {
      {{1.0, -0.5773502691896258, 0.0}, {0.0, 1.1547005383792517, 0.0}, {0.0, 0.0, 1.0}}};
};

// kSymmetryToFirst[k] is a permutation σ of an element's nodes with σ(0) = k that a rotation of
// the regular element of Def. 3 induces: read in the order p_σ(0), p_σ(1), …, the element has its
// node k first and the same node tetrahedra (each at most with its three edges turned), hence the
// same mean ratio, cost and derivatives with respect to that node, up to rounding. A polish step
// turns each element around its node so that the node is node 0 (element_passes.h,
// HessianListPass): then which node tetrahedra hold it, and where, is known at compile time. The
// pyramid has none: no rotation takes its apex to a base node.
template <ElementType kType>
concept HasFirstNodeSymmetry = requires {
  ElementTable<kType>::kSymmetryToFirst;
};

// Calls fn.template operator()<kType>() with the element type as a compile-time constant, so a
// run-time type selects one instantiation of a templated kernel (no virtual dispatch).
template <typename Fn>
decltype(auto) DispatchElementType(ElementType type, Fn&& fn) {
  switch (type) {
    case ElementType::kTetrahedron:
      return fn.template operator()<ElementType::kTetrahedron>();
    case ElementType::kHexahedron:
      return fn.template operator()<ElementType::kHexahedron>();
    case ElementType::kPyramid:
      return fn.template operator()<ElementType::kPyramid>();
    case ElementType::kPrism:
      break;
  }
  return fn.template operator()<ElementType::kPrism>();
}

}  // namespace getme
