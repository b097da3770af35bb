#pragma once

// The paper's element tables (Section 2.1 and eq. 9, Def. 3), typed in a second time from the
// paper's 1-based text so that the tests check the library's tables
// (core/getme/elements/element_tables.h) against an independent transcription instead of against
// themselves.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "getme/elements/element_type.h"

namespace getme::test {

using IndexTuple = std::vector<int>;

struct PaperTables {
  int node_count;
  std::vector<IndexTuple> faces;       // F, 0-based
  std::vector<IndexTuple> dual_faces;  // F̄, 0-based
  std::vector<IndexTuple> node_tets;   // N, 0-based
  Eigen::Matrix3d target;  // W of Def. 3 (columns: the regular node tetrahedron's edges)
};

namespace internal {

// The paper numbers nodes from 1; shifting here keeps the literals identical to the paper's text.
inline std::vector<IndexTuple> FromOneBased(std::vector<IndexTuple> tuples) {
  for (IndexTuple& tuple : tuples) {
    for (int& index : tuple) --index;
  }
  return tuples;
}

inline Eigen::Matrix3d FromColumns(const Eigen::Vector3d& c0, const Eigen::Vector3d& c1,
                                   const Eigen::Vector3d& c2) {
  Eigen::Matrix3d m;
  m << c0, c1, c2;
  return m;
}

}  // namespace internal

inline PaperTables MakePaperTables(ElementType type) {
  using internal::FromColumns;
  using internal::FromOneBased;
  const double s2 = std::sqrt(2.0);
  const double s3 = std::sqrt(3.0);
  switch (type) {
    case ElementType::kTetrahedron:
      return {4, FromOneBased({{1, 2, 3}, {1, 2, 4}, {2, 3, 4}, {3, 1, 4}}),
              FromOneBased({{1, 2, 4}, {1, 3, 2}, {1, 4, 3}, {2, 3, 4}}),
              FromOneBased({{1, 2, 3, 4}}),
              FromColumns({1, 0, 0}, {0.5, s3 / 2, 0}, {0.5, s3 / 6, std::sqrt(2.0 / 3.0)})};
    case ElementType::kHexahedron:
      return {
          8,
          FromOneBased(
              {{1, 2, 3, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 4, 8, 7}, {4, 1, 5, 8}, {5, 8, 7, 6}}),
          FromOneBased({{1, 2, 5},
                        {1, 3, 2},
                        {1, 4, 3},
                        {1, 5, 4},
                        {6, 5, 2},
                        {6, 2, 3},
                        {6, 3, 4},
                        {6, 4, 5}}),
          FromOneBased({{1, 4, 5, 2},
                        {2, 1, 6, 3},
                        {3, 2, 7, 4},
                        {4, 3, 8, 1},
                        {5, 8, 6, 1},
                        {6, 5, 7, 2},
                        {7, 6, 8, 3},
                        {8, 7, 5, 4}}),
          Eigen::Matrix3d::Identity()};
    case ElementType::kPyramid:
      return {5, FromOneBased({{1, 2, 3, 4}, {1, 2, 5}, {2, 3, 5}, {3, 4, 5}, {4, 1, 5}}),
              FromOneBased({{1, 2, 5}, {1, 3, 2}, {1, 4, 3}, {1, 5, 4}, {2, 3, 4, 5}}),
              FromOneBased({{1, 2, 4, 5}, {2, 3, 1, 5}, {3, 4, 2, 5}, {4, 1, 3, 5}}),
              FromColumns({1, 0, 0}, {0, 1, 0}, {0.5, 0.5, s2 / 2})};
    case ElementType::kPrism:
      break;
  }
  return {6, FromOneBased({{1, 2, 3}, {1, 2, 5, 4}, {2, 3, 6, 5}, {3, 1, 4, 6}, {4, 6, 5}}),
          FromOneBased({{1, 2, 4}, {1, 3, 2}, {1, 4, 3}, {5, 4, 2}, {5, 2, 3}, {5, 3, 4}}),
          FromOneBased(
              {{1, 2, 3, 4}, {2, 3, 1, 5}, {3, 1, 2, 6}, {4, 6, 5, 1}, {5, 4, 6, 2}, {6, 5, 4, 3}}),
          FromColumns({1, 0, 0}, {0.5, s3 / 2, 0}, {0, 0, 1})};
}

inline const PaperTables& Paper(ElementType type) {
  static const PaperTables kTables[kElementTypeCount] = {
      MakePaperTables(ElementType::kTetrahedron), MakePaperTables(ElementType::kHexahedron),
      MakePaperTables(ElementType::kPyramid), MakePaperTables(ElementType::kPrism)};
  return kTables[TypeIndex(type)];
}

// The geometric edges, derived from the faces rather than typed in: two nodes form an edge when
// they are consecutive on some face. Each edge appears once, as (smaller, larger).
inline std::vector<std::pair<int, int>> PaperEdges(ElementType type) {
  std::vector<std::pair<int, int>> edges;
  for (const IndexTuple& face : Paper(type).faces) {
    for (std::size_t i = 0; i < face.size(); ++i) {
      const int a = face[i];
      const int b = face[(i + 1) % face.size()];
      const std::pair<int, int> edge = {std::min(a, b), std::max(a, b)};
      if (std::find(edges.begin(), edges.end(), edge) == edges.end()) edges.push_back(edge);
    }
  }
  return edges;
}

}  // namespace getme::test
