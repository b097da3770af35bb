#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "formats/openfoam/foam_cursor.h"

namespace getme::formats {

// The FoamFile header dictionary of an OpenFOAM file (User Guide §4.2.2 "The FoamFile header"),
// as far as the polyMesh files need it. A file without a header is ASCII with 32-bit labels and
// 64-bit scalars, OpenFOAM's defaults.
struct FoamFileHeader {
  bool present = false;
  bool binary = false;     // format binary; (ascii otherwise)
  std::string class_name;  // vectorField, faceList, faceCompactList, labelList, polyBoundaryMesh
  int label_bytes = 4;     // arch "…;label=32|64;…"
  int scalar_bytes = 8;    // arch "…;scalar=32|64;…"
};

// One polyMesh file in memory: its name for messages, its text (gunzipped if it was gzip
// compressed), the header, and where the data after the header begins.
struct FoamFile {
  std::string name;  // as found in the directory: "points", "faces.gz", …
  bool gzipped = false;
  std::string text;
  FoamFileHeader header;
  std::size_t data_begin = 0;
};

// Parses the header of `raw` (decompressing it first when it starts with gzip's magic bytes,
// RFC 1952 §2.3.1, as OpenFOAM writes "writeCompression on" files: name.gz). InvalidArgument
// naming the file and line for a malformed header, an unknown format or an arch that is not
// little-endian with 32/64-bit labels and 32/64-bit scalars.
absl::StatusOr<FoamFile> ParseFoamFile(std::string name, std::string raw);

// Reads one list at the cursor (after white space and comments) in the file's encoding:
// ASCII "N ( items )", "( items )" without a count, or "N{item}" (a uniform list);
// binary "N (" + N items of raw little-endian bytes + ")". `what` names the list in messages.
// Real vectors: 3 scalars per item, ASCII items "(x y z)".
absl::StatusOr<std::vector<double>> ReadVectorList(FoamCursor& cursor, const FoamFileHeader& header,
                                                   absl::string_view what);
// `check` (if given) sees each label with its index and returns an error message for a bad
// one (empty if fine), which is reported at that label's line or byte.
using LabelCheck = std::function<std::string(std::int64_t index, std::int64_t label)>;
absl::StatusOr<std::vector<std::int64_t>> ReadLabelList(FoamCursor& cursor,
                                                        const FoamFileHeader& header,
                                                        absl::string_view what,
                                                        const LabelCheck& check = {});

// A face list in compact form: face f has the points labels[offsets[f] .. offsets[f+1]).
struct CompactFaces {
  std::vector<std::int64_t> offsets{0};
  std::vector<std::int64_t> labels;
  std::int64_t size() const { return static_cast<std::int64_t>(offsets.size()) - 1; }
};

// The faces file's data: class faceList — a list of label lists, ASCII "4(0 1 2 3)" items or
// binary "4(" + raw labels + ")" items — or class faceCompactList (what OpenFOAM v1806+ writes
// for binary faces): two label lists, the N+1 offsets, then the point labels. Checks that the
// offsets start at 0, never decrease and end at the number of labels, and that every face has
// at least 3 points, each one of the `point_count` points, none twice.
absl::StatusOr<CompactFaces> ReadFaces(FoamCursor& cursor, const FoamFileHeader& header,
                                       std::int64_t point_count);

// One patch of the boundary file (a polyBoundaryMesh: "N ( name { type …; nFaces n;
// startFace s; … } … )").
struct FoamPatch {
  std::string name;
  std::string type;
  std::int64_t start_face = 0;
  std::int64_t face_count = 0;
};
absl::StatusOr<std::vector<FoamPatch>> ReadBoundary(FoamCursor& cursor);

// After the last list: only white space and comments may follow.
absl::Status ExpectEndOfFile(FoamCursor& cursor);

// gzip (RFC 1952) compression and decompression through zlib.
absl::StatusOr<std::string> Gunzip(absl::string_view compressed, absl::string_view file_name);
absl::StatusOr<std::string> Gzip(absl::string_view bytes);

}  // namespace getme::formats
