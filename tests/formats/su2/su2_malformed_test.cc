// Every way the SU2 reader refuses a file, with the exact message: the line, the section and
// the field at fault.

#include <gtest/gtest.h>

#include <ostream>
#include <string>

#include "formats/su2/su2_reader.h"

namespace getme::formats {
namespace {

struct Case {
  const char* name;
  std::string text;
  std::string message;
};

// A valid file to break: one tetrahedron, four points, one marker with one triangle.
std::string Valid(const std::string& elements = "10 0 1 2 3\n",
                  const std::string& points = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n",
                  const std::string& markers =
                      "NMARK= 1\nMARKER_TAG= wall\nMARKER_ELEMS= 1\n"
                      "5 0 2 1\n") {
  return "NDIME= 3\nNELEM= 1\n" + elements + "NPOIN= 4\n" + points + markers;
}

// gtest prints the case by name rather than as bytes.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class Su2Malformed : public ::testing::TestWithParam<Case> {};

TEST_P(Su2Malformed, IsRefusedNamingLineAndField) {
  const absl::StatusOr<MeshDocument> document = ParseSu2(GetParam().text);
  EXPECT_EQ(document.status(), absl::InvalidArgumentError(GetParam().message));
}

TEST(Su2Malformed, TheValidFileToBreakReads) {
  const absl::StatusOr<MeshDocument> document = ParseSu2(Valid());
  ASSERT_TRUE(document.ok()) << document.status();
  EXPECT_EQ(document->grid.cells.size(), 2);
}

INSTANTIATE_TEST_SUITE_P(
    AllErrors, Su2Malformed,
    ::testing::Values(
        Case{"Empty", "", "line 1: the file ends without NDIME= (the dimension)"},
        Case{"NoElements", "NDIME= 3\nNPOIN= 0\n",
             "line 2: the file ends without NELEM= (the elements)"},
        Case{"NoPoints", "NDIME= 3\nNELEM= 0\n",
             "line 2: the file ends without NPOIN= (the points)"},
        Case{"TwoDimensional", "NDIME= 2\n",
             "line 1: NDIME= 2: only 3D meshes are read (getme smooths volume meshes)"},
        Case{"DimensionNotANumber", "NDIME= three\n", "line 1: NDIME= 'three' is not a dimension"},
        Case{"DimensionTwice", "NDIME= 3\n% comment\nNDIME= 3\n",
             "line 3: a second NDIME= (the first is at line 1)"},
        Case{"ElementsBeforeDimension", "NELEM= 0\n",
             "line 1: NELEM= before NDIME=: the dimension comes first"},
        Case{"MultiZone", "NZONE= 2\n",
             "line 1: NZONE= 2: multi-zone SU2 meshes are not supported; write each zone to a "
             "file of its own"},
        Case{"SecondZone", "NDIME= 3\nIZONE= 2\n",
             "line 2: IZONE= 2: multi-zone SU2 meshes are not supported; write each zone to a "
             "file of its own"},
        Case{"BadCount", "NDIME= 3\nNELEM= -1\n", "line 2: NELEM= '-1' is not a count"},
        Case{"CountWithTwoNumbers", "NDIME= 3\nNELEM= 1 1\n",
             "line 2: NELEM= '1 1' is not a count"},
        Case{"PointsTwice", Valid() + "NPOIN= 0\n",
             "line 13: a second NPOIN= (the first is at line 4)"},
        Case{"FileEndsInElements", "NDIME= 3\nNELEM= 3\n10 0 1 2 3\n",
             "line 2: NELEM= 3 announces 3 elements; the file ends after 1"},
        Case{"SectionInsteadOfRow", "NDIME= 3\nNELEM= 2\n10 0 1 2 3\nNPOIN= 4\n",
             "line 4: expected elements row 1 of NELEM= 2 (line 2), found 'NPOIN= 4'"},
        Case{"RowsBeyondTheCount", Valid("10 0 1 2 3\n10 0 1 2 3\n"),
             "line 4: '10 0 1 2 3' is not a section header (NAME= value): does a count announce "
             "fewer rows than follow?"},
        Case{"UnknownElementType", Valid("11 0 1 2 3 0 1 2 3\n"),
             "line 3: NELEM element 0: unknown element type 11 (volume elements: 10 tetrahedron, "
             "12 hexahedron, 13 prism, 14 pyramid)"},
        Case{"ElementTypeNotANumber", Valid("tet 0 1 2 3\n"),
             "line 3: NELEM element 0: element type 'tet' is not an integer"},
        Case{"ShortElementRow", Valid("10 0 1 2\n"),
             "line 3: NELEM element 0: a tetrahedron (type 10) has 4 nodes and an optional index; "
             "the row has 3 values after the type"},
        Case{"LongElementRow", Valid("10 0 1 2 3 0 7\n"),
             "line 3: NELEM element 0: a tetrahedron (type 10) has 4 nodes and an optional index; "
             "the row has 6 values after the type"},
        Case{"NegativeNode", Valid("10 0 -1 2 3\n"),
             "line 3: NELEM element 0: node 2 '-1' is not a point index"},
        Case{"ElementIndexNotANumber", Valid("10 0 1 2 3 x\n"),
             "line 3: NELEM element 0: element index 'x' is not an integer"},
        Case{"NodeOutOfRange", Valid("10 0 1 2 4\n"),
             "line 3: NELEM element 0: node 4 refers to point 4, out of range 0..3 (NPOIN= 4 at "
             "line 4)"},
        Case{
            "MarkerNodeOutOfRange",
            Valid("10 0 1 2 3\n", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n",
                  "NMARK= 1\nMARKER_TAG= wall\nMARKER_ELEMS= 1\n5 0 9 1\n"),
            "line 12: marker 'wall' element 0: node 2 refers to point 9, out of range 0..3 (NPOIN= "
            "4 at line 4)"},
        Case{"ShortPointRow", Valid("10 0 1 2 3\n", "0 0 0\n1 0\n0 1 0\n0 0 1\n"),
             "line 6: NPOIN point 1: expected 3 coordinates and an optional index, found 2 values"},
        Case{"CoordinateNotANumber", Valid("10 0 1 2 3\n", "0 0 0\n1 0 0\n0 y 0\n0 0 1\n"),
             "line 7: NPOIN point 2: coordinate 1 'y' is not a finite number"},
        Case{"InfiniteCoordinate", Valid("10 0 1 2 3\n", "0 0 0\n1 0 0\n0 1 0\n0 0 inf\n"),
             "line 8: NPOIN point 3: coordinate 2 'inf' is not a finite number"},
        Case{"PointIndexNotANumber", Valid("10 0 1 2 3\n", "0 0 0 a\n1 0 0\n0 1 0\n0 0 1\n"),
             "line 5: NPOIN point 0: point index 'a' is not an integer"},
        Case{"FileEndsInMarkers",
             Valid("10 0 1 2 3\n", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n", "NMARK= 2\n"),
             "line 9: NMARK= 2 announces 2 markers; the file ends after 0"},
        Case{"MarkerWithoutTag",
             Valid("10 0 1 2 3\n", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n", "NMARK= 1\nMARKER_ELEMS= 0\n"),
             "line 10: expected MARKER_TAG= for marker 1 of NMARK= 1 (line 9), found "
             "'MARKER_ELEMS= 0'"},
        Case{"MarkerWithoutName",
             Valid("10 0 1 2 3\n", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n", "NMARK= 1\nMARKER_TAG=\n"),
             "line 10: MARKER_TAG= without a name"},
        Case{"MarkerTwice",
             Valid("10 0 1 2 3\n", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n",
                   "NMARK= 2\nMARKER_TAG= wall\nMARKER_ELEMS= 0\nMARKER_TAG= wall\n"),
             "line 12: marker 'wall' again (its first MARKER_TAG= is at line 10)"},
        Case{"MarkerEndsBeforeElems",
             Valid("10 0 1 2 3\n", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n", "NMARK= 1\nMARKER_TAG= wall\n"),
             "line 10: marker 'wall': the file ends before MARKER_ELEMS="},
        Case{"MarkerWithoutElems",
             Valid("10 0 1 2 3\n", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n",
                   "NMARK= 1\nMARKER_TAG= wall\nNELEM= 0\n"),
             "line 11: marker 'wall': expected MARKER_ELEMS=, found 'NELEM= 0'"},
        Case{"MarkerElemsNotACount",
             Valid("10 0 1 2 3\n", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n",
                   "NMARK= 1\nMARKER_TAG= wall\nMARKER_ELEMS= many\n"),
             "line 11: marker 'wall': MARKER_ELEMS= 'many' is not a count"},
        Case{"UnknownBoundaryType",
             Valid("10 0 1 2 3\n", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n",
                   "NMARK= 1\nMARKER_TAG= wall\nMARKER_ELEMS= 1\n10 0 1 2 3\n"),
             "line 12: marker 'wall' element 0: unknown element type 10 (marker elements: 5 "
             "triangle, 9 quadrilateral, 3 line)"},
        Case{"ShortBoundaryRow",
             Valid("10 0 1 2 3\n", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n",
                   "NMARK= 1\nMARKER_TAG= wall\nMARKER_ELEMS= 1\n9 0 1 2\n"),
             "line 12: marker 'wall' element 0: a quadrilateral (type 9) has 4 nodes and an "
             "optional index; the row has 3 values after the type"},
        Case{"MarkerOutsideNmark", Valid() + "MARKER_TAG= extra\n",
             "line 13: MARKER_TAG= outside the markers: NMARK= at line 9 announces fewer markers"},
        Case{"MarkerWithoutNmark", "NDIME= 3\nMARKER_TAG= wall\n",
             "line 2: MARKER_TAG= outside the markers: no NMARK= comes before it"},
        Case{"UnknownSectionEarly", "NDIME= 3\nNPERIODIC= 1\n",
             "line 2: unknown section 'NPERIODIC=' before the mesh is complete (an SU2 mesh has "
             "NDIME=, NELEM=, NPOIN= and NMARK=)"},
        Case{"MeshSectionInTail", "NDIME= 3\nNELEM= 0\nNPOIN= 0\nNPERIODIC= 1\n1 2 3\nNMARK= 0\n",
             "line 6: NMARK= after the section 'NPERIODIC=' at line 4, which getme keeps as it is "
             "without reading it: move the mesh sections before it"}),
    [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace getme::formats
