#pragma once

// Straightforward Eigen re-computations of validity (Def. 2), mean ratio (Def. 3) and warpage
// (Sec. 4.4) from the paper's tables (N before eq. (9), W of eq. (10)) typed in here. They share
// no code with core/getme/elements/element_quality.h: W is built from its columns and inverted by
// Eigen, and the mean ratio uses std::pow instead of cbrt.

#include <Eigen/Core>
#include <vector>

#include "getme/elements/element_type.h"

namespace getme::mesh_test {

using Points = std::vector<Eigen::Vector3d>;

bool ReferenceIsValid(ElementType type, const Points& p);
// Mean ratio of a valid element, without clamping; 0 for an invalid one
// (docs/paper-notes.md#invalid-elements).
double ReferenceMeanRatio(ElementType type, const Points& p);
// Maximum warpage over the element's quad faces; 0 without quad faces.
double ReferenceWarpage(ElementType type, const Points& p);

}  // namespace getme::mesh_test
