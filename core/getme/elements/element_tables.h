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
  static constexpr std::array<EdgeIndices, 9> kEdges = {
      {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}, {0, 3}, {1, 4}, {2, 5}}};
  // W⁻¹ for W columns (1,0,0) (1/2,√3/2,0) (0,0,1).
  static constexpr Matrix3Rows kTargetInverse = {
      {{1.0, -0.5773502691896258, 0.0}, {0.0, 1.1547005383792517, 0.0}, {0.0, 0.0, 1.0}}};
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
