#include "formats/openfoam/foam_file.h"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <limits>
#include <map>
#include <type_traits>
#include <utility>

#include "absl/strings/match.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"

namespace getme::formats {
namespace {

// A uniform list "N{v}" holds N copies of one value in a few bytes; this bounds what such a
// list may make us allocate (OpenFOAM writes one only when all values are equal, e.g. the owner
// list of a one-cell mesh).
constexpr std::int64_t kMaxUniformListSize = std::int64_t{1} << 20;

absl::Status ParseArch(const std::string& arch, FoamCursor& cursor, FoamFileHeader& header) {
  for (const absl::string_view part : absl::StrSplit(arch, ';', absl::SkipEmpty())) {
    if (part == "LSB") continue;
    if (part == "MSB") {
      return cursor.Error("arch \"MSB\": big-endian binary files are not supported");
    }
    int* bytes = nullptr;
    absl::string_view value;
    if (absl::StartsWith(part, "label=")) {
      bytes = &header.label_bytes;
      value = part.substr(6);
    } else if (absl::StartsWith(part, "scalar=")) {
      bytes = &header.scalar_bytes;
      value = part.substr(7);
    } else {
      continue;  // other keys (none defined today) do not change the layout we read
    }
    if (value != "32" && value != "64") {
      return cursor.Error(
          absl::StrCat("arch \"", arch, "\": ", part, " is not supported (32 or 64 bits)"));
    }
    *bytes = value == "32" ? 4 : 8;
  }
  return absl::OkStatus();
}

absl::Status ParseHeader(FoamCursor& cursor, FoamFileHeader& header) {
  if (absl::Status status = cursor.Expect('{', "after FoamFile"); !status.ok()) return status;
  std::map<std::string, std::string> entries;
  while (true) {
    if (absl::Status status = cursor.SkipSpace(); !status.ok()) return status;
    if (cursor.Peek() == '}') {
      cursor.set_position(cursor.position() + 1);
      break;
    }
    absl::StatusOr<std::string> key = cursor.ReadWord("a FoamFile header keyword or '}'");
    if (!key.ok()) return key.status();
    std::string value;
    while (true) {
      if (absl::Status status = cursor.SkipSpace(); !status.ok()) return status;
      if (cursor.Peek() == ';') break;
      absl::StatusOr<std::string> word = cursor.ReadWord(absl::StrCat("the value of ", *key));
      if (!word.ok()) return word.status();
      if (value.empty()) value = *std::move(word);
    }
    cursor.set_position(cursor.position() + 1);
    entries[*key] = value;
  }
  header.present = true;
  if (const auto format = entries.find("format"); format != entries.end()) {
    if (format->second != "ascii" && format->second != "binary") {
      return cursor.Error(
          absl::StrCat("FoamFile format '", format->second, "' is neither ascii nor binary"));
    }
    header.binary = format->second == "binary";
  }
  if (const auto name = entries.find("class"); name != entries.end())
    header.class_name = name->second;
  if (const auto arch = entries.find("arch"); arch != entries.end()) {
    return ParseArch(arch->second, cursor, header);
  }
  return absl::OkStatus();
}

// How a list starts: its size (-1 if the ASCII list gives none) and whether it is uniform.
struct ListStart {
  std::int64_t size = -1;
  bool uniform = false;
};

absl::StatusOr<ListStart> ReadListStart(FoamCursor& cursor, const FoamFileHeader& header,
                                        absl::string_view what) {
  if (absl::Status status = cursor.SkipSpace(); !status.ok()) return status;
  ListStart start;
  if (cursor.Peek() != '(' || header.binary) {
    absl::StatusOr<std::int64_t> size = cursor.ReadInteger(absl::StrCat("the size of ", what));
    if (!size.ok()) return size.status();
    if (*size < 0) return cursor.Error(absl::StrCat(what, ": negative size ", *size));
    start.size = *size;
    if (absl::Status status = cursor.SkipSpace(); !status.ok()) return status;
  }
  if (cursor.Peek() == '{' && !header.binary) {
    if (start.size > kMaxUniformListSize) {
      return cursor.Error(absl::StrCat(what, ": uniform list of ", start.size,
                                       " entries exceeds the limit of ", kMaxUniformListSize));
    }
    start.uniform = true;
  } else if (cursor.Peek() != '(') {
    return cursor.Error(absl::StrCat("expected '(' to open ", what));
  }
  cursor.set_position(cursor.position() + 1);
  return start;
}

// Reads `count` binary values of `bytes` each as int64 or double.
template <typename Out>
absl::Status ReadBinaryValues(FoamCursor& cursor, std::int64_t count, int bytes,
                              absl::string_view what, std::vector<Out>& out,
                              const LabelCheck& check = {}) {
  const std::size_t remaining = cursor.text().size() - cursor.position();
  if (static_cast<std::uint64_t>(count) > remaining / static_cast<std::size_t>(bytes)) {
    return cursor.Error(absl::StrCat(what, ": ", count, " values of ", bytes,
                                     " bytes need more than the ", remaining,
                                     " bytes left in the file"));
  }
  absl::StatusOr<absl::string_view> block =
      cursor.ReadBytes(static_cast<std::size_t>(count) * bytes, what);
  if (!block.ok()) return block.status();
  const std::size_t first = out.size();
  out.resize(first + static_cast<std::size_t>(count));
  const char* data = block->data();
  for (std::int64_t i = 0; i < count; ++i, data += bytes) {
    if constexpr (std::is_same_v<Out, double>) {
      if (bytes == 8) {
        std::memcpy(&out[first + i], data, 8);
      } else {
        float value = 0;
        std::memcpy(&value, data, 4);
        out[first + i] = value;
      }
    } else {
      if (bytes == 8) {
        std::memcpy(&out[first + i], data, 8);
      } else {
        std::int32_t value = 0;
        std::memcpy(&value, data, 4);
        out[first + i] = value;
      }
      if (check) {
        if (std::string message = check(i, out[first + i]); !message.empty()) {
          return cursor.ErrorAt(cursor.position() - block->size() + i * bytes, message);
        }
      }
    }
  }
  return absl::OkStatus();
}

absl::Status ExpectClose(FoamCursor& cursor, char close, absl::string_view what) {
  return cursor.Expect(close, absl::StrCat("to close ", what));
}

// An ASCII list's items, until its ')' (or `size` of them), each read by `read_item`.
template <typename ReadItem>
absl::Status ReadAsciiItems(FoamCursor& cursor, std::int64_t size, absl::string_view what,
                            ReadItem read_item) {
  for (std::int64_t item = 0; size < 0 || item < size; ++item) {
    if (absl::Status status = cursor.SkipSpace(); !status.ok()) return status;
    if (cursor.Peek() == ')') {
      if (size < 0) break;
      return cursor.Error(absl::StrCat(what, ": ')' after ", item, " of ", size, " entries"));
    }
    if (cursor.AtEnd()) return cursor.Error(absl::StrCat(what, ": the file ends inside the list"));
    if (absl::Status status = read_item(item); !status.ok()) return status;
  }
  return ExpectClose(cursor, ')', what);
}

absl::Status ReadAsciiVector(FoamCursor& cursor, std::int64_t item, absl::string_view what,
                             std::vector<double>& out) {
  const std::string entry = absl::StrCat(what, " entry ", item);
  if (absl::Status status = cursor.Expect('(', absl::StrCat("to open ", entry)); !status.ok()) {
    return status;
  }
  for (int k = 0; k < 3; ++k) {
    absl::StatusOr<double> value = cursor.ReadReal(absl::StrCat(entry, " component ", k));
    if (!value.ok()) return value.status();
    out.push_back(*value);
  }
  return ExpectClose(cursor, ')', entry);
}

// A capacity guess that a malformed size cannot blow up: each item takes at least
// `min_bytes` of the remaining text.
std::size_t SafeReserve(const FoamCursor& cursor, std::int64_t size, std::size_t min_bytes) {
  const std::size_t remaining = (cursor.text().size() - cursor.position()) / min_bytes;
  return size < 0 ? 0 : std::min(static_cast<std::size_t>(size), remaining);
}

}  // namespace

absl::StatusOr<FoamFile> ParseFoamFile(std::string name, std::string raw) {
  FoamFile file;
  file.name = std::move(name);
  if (raw.size() >= 2 && static_cast<unsigned char>(raw[0]) == 0x1f &&
      static_cast<unsigned char>(raw[1]) == 0x8b) {
    absl::StatusOr<std::string> text = Gunzip(raw, file.name);
    if (!text.ok()) return text.status();
    file.text = *std::move(text);
    file.gzipped = true;
  } else {
    file.text = std::move(raw);
  }
  FoamCursor cursor(file.name, file.text);
  if (absl::Status status = cursor.SkipSpace(); !status.ok()) return status;
  const std::size_t start = cursor.position();
  if (file.text.compare(start, 8, "FoamFile") == 0 &&
      (start + 8 == file.text.size() ||
       !std::isalnum(static_cast<unsigned char>(file.text[start + 8])))) {
    cursor.set_position(start + 8);
    if (absl::Status status = ParseHeader(cursor, file.header); !status.ok()) return status;
    file.data_begin = cursor.position();
  } else {
    file.data_begin = 0;
  }
  return file;
}

absl::StatusOr<std::vector<double>> ReadVectorList(FoamCursor& cursor, const FoamFileHeader& header,
                                                   absl::string_view what) {
  absl::StatusOr<ListStart> start = ReadListStart(cursor, header, what);
  if (!start.ok()) return start.status();
  std::vector<double> values;
  if (header.binary) {
    if (start->size > std::numeric_limits<std::int64_t>::max() / 3) {
      return cursor.Error(absl::StrCat(what, ": size ", start->size, " is too large"));
    }
    if (absl::Status status =
            ReadBinaryValues(cursor, 3 * start->size, header.scalar_bytes, what, values);
        !status.ok()) {
      return status;
    }
    if (absl::Status status = ExpectClose(cursor, ')', what); !status.ok()) return status;
    return values;
  }
  if (start->uniform) {
    if (absl::Status status = ReadAsciiVector(cursor, 0, what, values); !status.ok()) return status;
    if (absl::Status status = ExpectClose(cursor, '}', what); !status.ok()) return status;
    values.resize(3 * static_cast<std::size_t>(start->size));
    for (std::size_t i = 3; i < values.size(); ++i) values[i] = values[i % 3];
    return values;
  }
  values.reserve(3 * SafeReserve(cursor, start->size, 7));
  if (absl::Status status = ReadAsciiItems(
          cursor, start->size, what,
          [&](std::int64_t item) { return ReadAsciiVector(cursor, item, what, values); });
      !status.ok()) {
    return status;
  }
  return values;
}

absl::StatusOr<std::vector<std::int64_t>> ReadLabelList(FoamCursor& cursor,
                                                        const FoamFileHeader& header,
                                                        absl::string_view what,
                                                        const LabelCheck& check) {
  absl::StatusOr<ListStart> start = ReadListStart(cursor, header, what);
  if (!start.ok()) return start.status();
  std::vector<std::int64_t> labels;
  if (header.binary) {
    if (absl::Status status =
            ReadBinaryValues(cursor, start->size, header.label_bytes, what, labels, check);
        !status.ok()) {
      return status;
    }
    if (absl::Status status = ExpectClose(cursor, ')', what); !status.ok()) return status;
    return labels;
  }
  if (start->uniform) {
    absl::StatusOr<std::int64_t> value = cursor.ReadInteger(absl::StrCat(what, " entry 0"));
    if (!value.ok()) return value.status();
    if (check) {
      for (std::int64_t i = 0; i < start->size; ++i) {
        if (std::string message = check(i, *value); !message.empty()) return cursor.Error(message);
      }
    }
    if (absl::Status status = ExpectClose(cursor, '}', what); !status.ok()) return status;
    labels.assign(static_cast<std::size_t>(start->size), *value);
    return labels;
  }
  labels.reserve(SafeReserve(cursor, start->size, 2));
  if (absl::Status status =
          ReadAsciiItems(cursor, start->size, what,
                         [&](std::int64_t item) -> absl::Status {
                           absl::StatusOr<std::int64_t> value =
                               cursor.ReadInteger(absl::StrCat(what, " entry ", item));
                           if (!value.ok()) return value.status();
                           if (check) {
                             if (std::string message = check(item, *value); !message.empty()) {
                               return cursor.Error(message);
                             }
                           }
                           labels.push_back(*value);
                           return absl::OkStatus();
                         });
      !status.ok()) {
    return status;
  }
  return labels;
}

absl::StatusOr<CompactFaces> ReadFaces(FoamCursor& cursor, const FoamFileHeader& header,
                                       std::int64_t point_count) {
  CompactFaces faces;
  const auto point_message = [point_count](std::int64_t face, std::int64_t point) {
    return absl::StrCat("face ", face, " refers to point ", point, ", but the points file has ",
                        point_count, " points");
  };
  // Size and repeated points of face `face`, once its labels are in.
  const auto face_message = [&faces](std::int64_t face) -> std::string {
    const std::int64_t begin = faces.offsets[face];
    const std::int64_t size = faces.offsets[face + 1] - begin;
    if (size < 3)
      return absl::StrCat("face ", face, " has ", size, " points; a face has at least 3");
    for (std::int64_t i = 1; i < size; ++i) {
      for (std::int64_t j = 0; j < i; ++j) {
        if (faces.labels[begin + i] == faces.labels[begin + j]) {
          return absl::StrCat("face ", face, " lists point ", faces.labels[begin + i], " twice");
        }
      }
    }
    return {};
  };
  if (header.class_name == "faceCompactList") {
    const std::size_t offsets_at = cursor.position();
    absl::StatusOr<std::vector<std::int64_t>> offsets =
        ReadLabelList(cursor, header, "the face offsets (faceCompactList)");
    if (!offsets.ok()) return offsets.status();
    if (offsets->empty()) offsets->push_back(0);
    if ((*offsets)[0] != 0) {
      return cursor.ErrorAt(offsets_at, absl::StrCat("faceCompactList: the first offset is ",
                                                     (*offsets)[0], ", not 0"));
    }
    for (std::size_t face = 0; face + 1 < offsets->size(); ++face) {
      if ((*offsets)[face + 1] < (*offsets)[face]) {
        return cursor.ErrorAt(
            offsets_at,
            absl::StrCat("faceCompactList: offset ", face + 1, " (", (*offsets)[face + 1],
                         ") is less than offset ", face, " (", (*offsets)[face], ")"));
      }
    }
    const std::size_t labels_at = cursor.position();
    std::int64_t face = 0;
    absl::StatusOr<std::vector<std::int64_t>> labels =
        ReadLabelList(cursor, header, "the face point labels (faceCompactList)",
                      [&](std::int64_t index, std::int64_t point) -> std::string {
                        while (face + 1 < static_cast<std::int64_t>(offsets->size()) &&
                               (*offsets)[face + 1] <= index) {
                          ++face;
                        }
                        if (point < 0 || point >= point_count) return point_message(face, point);
                        return {};
                      });
    if (!labels.ok()) return labels.status();
    if (offsets->back() != static_cast<std::int64_t>(labels->size())) {
      return cursor.ErrorAt(labels_at,
                            absl::StrCat("faceCompactList: the last offset is ", offsets->back(),
                                         ", but there are ", labels->size(), " point labels"));
    }
    faces.offsets = *std::move(offsets);
    faces.labels = *std::move(labels);
    for (std::int64_t f = 0; f < faces.size(); ++f) {
      if (std::string message = face_message(f); !message.empty()) {
        return cursor.ErrorAt(
            header.binary ? labels_at + faces.offsets[f] * header.label_bytes : labels_at, message);
      }
    }
    return faces;
  }
  // faceList: a list of label lists, the inner lists in the file's encoding.
  absl::StatusOr<ListStart> start = ReadListStart(cursor, FoamFileHeader{}, "the face list");
  if (!start.ok()) return start.status();
  if (start->uniform) return cursor.Error("the face list: a uniform face list is not supported");
  faces.offsets.reserve(SafeReserve(cursor, start->size, 4) + 1);
  if (absl::Status status =
          ReadAsciiItems(cursor, start->size, "the face list",
                         [&](std::int64_t item) -> absl::Status {
                           const std::size_t face_at = cursor.position();
                           absl::StatusOr<std::vector<std::int64_t>> face =
                               ReadLabelList(cursor, header, absl::StrCat("face ", item),
                                             [&](std::int64_t, std::int64_t point) -> std::string {
                                               if (point < 0 || point >= point_count)
                                                 return point_message(item, point);
                                               return {};
                                             });
                           if (!face.ok()) return face.status();
                           faces.labels.insert(faces.labels.end(), face->begin(), face->end());
                           faces.offsets.push_back(static_cast<std::int64_t>(faces.labels.size()));
                           if (std::string message = face_message(item); !message.empty()) {
                             return cursor.ErrorAt(face_at, message);
                           }
                           return absl::OkStatus();
                         });
      !status.ok()) {
    return status;
  }
  return faces;
}

absl::StatusOr<std::vector<FoamPatch>> ReadBoundary(FoamCursor& cursor) {
  absl::StatusOr<ListStart> start = ReadListStart(cursor, FoamFileHeader{}, "the patch list");
  if (!start.ok()) return start.status();
  if (start->uniform) return cursor.Error("the patch list: expected '(', found '{'");
  std::vector<FoamPatch> patches;
  while (true) {
    if (absl::Status status = cursor.SkipSpace(); !status.ok()) return status;
    if (cursor.Peek() == ')') break;
    if (cursor.AtEnd()) return cursor.Error("the patch list: the file ends inside the list");
    const std::size_t patch_at = cursor.position();
    FoamPatch patch;
    absl::StatusOr<std::string> name = cursor.ReadWord("a patch name");
    if (!name.ok()) return name.status();
    patch.name = *std::move(name);
    const std::string what = absl::StrCat("patch '", patch.name, "'");
    if (absl::Status status = cursor.Expect('{', absl::StrCat("after ", what)); !status.ok()) {
      return status;
    }
    bool has_start = false;
    bool has_count = false;
    while (true) {
      if (absl::Status status = cursor.SkipSpace(); !status.ok()) return status;
      if (cursor.Peek() == '}') {
        cursor.set_position(cursor.position() + 1);
        break;
      }
      absl::StatusOr<std::string> key = cursor.ReadWord(absl::StrCat("a keyword of ", what));
      if (!key.ok()) return key.status();
      // A sub-dictionary ("key { … }") ends at its brace, without ';'.
      if (absl::Status status = cursor.SkipSpace(); !status.ok()) return status;
      if (cursor.Peek() == '{') {
        int depth = 0;
        do {
          if (absl::Status status = cursor.SkipSpace(); !status.ok()) return status;
          if (cursor.AtEnd()) {
            return cursor.Error(absl::StrCat(what, ": the file ends inside '", *key, "'"));
          }
          const char c = cursor.Peek();
          if (c == '{' || c == '}') {
            depth += c == '{' ? 1 : -1;
            cursor.set_position(cursor.position() + 1);
          } else if (c == '(' || c == ')' || c == ';') {
            cursor.set_position(cursor.position() + 1);
          } else if (absl::StatusOr<std::string> word = cursor.ReadWord("a word"); !word.ok()) {
            return word.status();
          }
        } while (depth > 0);
        continue;
      }
      // The value: words, strings and parenthesised lists ("inGroups 1(wall);") up to ';'.
      std::string first;
      int depth = 0;
      while (true) {
        if (absl::Status status = cursor.SkipSpace(); !status.ok()) return status;
        const char c = cursor.Peek();
        if (cursor.AtEnd()) {
          return cursor.Error(absl::StrCat(what, ": the file ends inside '", *key, "'"));
        }
        if (c == ';' && depth == 0) break;
        if (c == '(' || c == ')' || c == '{' || c == '}' || c == ';') {
          depth += c == '(' || c == '{' ? 1 : c == ')' || c == '}' ? -1 : 0;
          if (depth < 0) {
            return cursor.Error(
                absl::StrCat(what, ": unbalanced '", std::string(1, c), "' in '", *key, "'"));
          }
          cursor.set_position(cursor.position() + 1);
          continue;
        }
        absl::StatusOr<std::string> word = cursor.ReadWord(absl::StrCat("the value of ", *key));
        if (!word.ok()) return word.status();
        if (first.empty() && depth == 0) first = *std::move(word);
      }
      cursor.set_position(cursor.position() + 1);
      if (*key == "type") patch.type = first;
      if (*key == "startFace" || *key == "nFaces") {
        std::int64_t value = 0;
        if (!absl::SimpleAtoi(first, &value) || value < 0) {
          return cursor.Error(
              absl::StrCat(what, ": ", *key, " '", first, "' is not a non-negative integer"));
        }
        (*key == "startFace" ? patch.start_face : patch.face_count) = value;
        (*key == "startFace" ? has_start : has_count) = true;
      }
    }
    if (!has_start || !has_count) {
      return cursor.ErrorAt(
          patch_at, absl::StrCat(what, " has no ", has_start ? "nFaces" : "startFace", " entry"));
    }
    patches.push_back(std::move(patch));
  }
  cursor.set_position(cursor.position() + 1);
  if (start->size >= 0 && start->size != static_cast<std::int64_t>(patches.size())) {
    return cursor.Error(absl::StrCat("the patch list: its size says ", start->size,
                                     " patches, but it has ", patches.size()));
  }
  return patches;
}

absl::Status ExpectEndOfFile(FoamCursor& cursor) {
  if (absl::Status status = cursor.SkipSpace(); !status.ok()) return status;
  if (!cursor.AtEnd()) return cursor.Error("unexpected content after the data");
  return absl::OkStatus();
}

absl::StatusOr<std::string> Gunzip(absl::string_view compressed, absl::string_view file_name) {
  z_stream stream{};
  // 16 + MAX_WBITS: a gzip wrapper (zlib manual, inflateInit2).
  if (inflateInit2(&stream, 16 + MAX_WBITS) != Z_OK) {
    return absl::InternalError("zlib: inflateInit2 failed");
  }
  std::string out;
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data()));
  stream.avail_in = static_cast<uInt>(compressed.size());
  int result = Z_OK;
  while (result == Z_OK) {
    const std::size_t used = out.size();
    out.resize(std::max<std::size_t>(2 * used, 1 << 16));
    stream.next_out = reinterpret_cast<Bytef*>(out.data() + used);
    stream.avail_out = static_cast<uInt>(out.size() - used);
    result = inflate(&stream, Z_NO_FLUSH);
    out.resize(out.size() - stream.avail_out);
    if (result == Z_BUF_ERROR && stream.avail_in == 0) break;
    if (result == Z_BUF_ERROR) result = Z_OK;
  }
  const std::string message = stream.msg != nullptr ? stream.msg : "";
  inflateEnd(&stream);
  if (result != Z_STREAM_END) {
    return absl::InvalidArgumentError(
        absl::StrCat(file_name, ": gzip data ", result == Z_BUF_ERROR ? "truncated" : "corrupt",
                     message.empty() ? "" : absl::StrCat(" (", message, ")"), " after ", out.size(),
                     " decompressed bytes"));
  }
  return out;
}

absl::StatusOr<std::string> Gzip(absl::string_view bytes) {
  z_stream stream{};
  if (deflateInit2(&stream, Z_DEFAULT_COMPRESSION, Z_DEFLATED, 16 + MAX_WBITS, 8,
                   Z_DEFAULT_STRATEGY) != Z_OK) {
    return absl::InternalError("zlib: deflateInit2 failed");
  }
  std::string out(deflateBound(&stream, static_cast<uLong>(bytes.size())) + 32, '\0');
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  stream.avail_in = static_cast<uInt>(bytes.size());
  stream.next_out = reinterpret_cast<Bytef*>(out.data());
  stream.avail_out = static_cast<uInt>(out.size());
  const int result = deflate(&stream, Z_FINISH);
  out.resize(out.size() - stream.avail_out);
  deflateEnd(&stream);
  if (result != Z_STREAM_END) return absl::InternalError("zlib: deflate did not finish");
  return out;
}

}  // namespace getme::formats
