// VTK's XML PolyData (.vtp), as "VTK File Formats" defines it:
//   <VTKFile type="PolyData" byte_order=... header_type=... compressor=...>
//     <PolyData><Piece NumberOfPoints=... NumberOfPolys=... NumberOfStrips=...>
//       <Points><DataArray NumberOfComponents="3" .../></Points>
//       <Polys>  <DataArray Name="connectivity"/><DataArray Name="offsets"/></Polys>
//       <Strips> the same </Strips>
//   </Piece>...</PolyData><AppendedData encoding="raw|base64">_...</AppendedData></VTKFile>
// Every DataArray format: "ascii" (text), "binary" (base64 inline) and
// "appended" (at `offset` in the appended data, raw or base64); binary data
// in either byte order, with a UInt32 or UInt64 header, uncompressed or
// compressed by vtkZLibDataCompressor (blocks inflated with zlib). Offsets
// are each cell's end, as the format has them. Several pieces are joined.
// Verts, Lines, PointData and CellData are read past. The XML is parsed by
// expat; the appended block, which may be raw bytes, is cut off first.
// Every count is held against the bytes that hold it before anything is
// allocated, and a compressed block may claim at most what deflate can
// expand to (1,032 bytes per byte). No two arrays may read the same
// appended bytes.
#include <expat.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <map>
#include <optional>
#include <string_view>
#include <vector>

#include "common/user_error.hpp"
#include "mesh/io/binary_values.hpp"
#include "mesh/io/byte_cursor.hpp"
#include "mesh/io/format_readers.hpp"
#include "mesh/plural.hpp"

namespace meshparticles {

namespace {

// The most bytes deflate can expand one byte to (zlib's technical notes).
constexpr std::uint64_t kMaxInflation = 1032;

using Attributes = std::map<std::string, std::string, std::less<>>;

struct DataArray {
  Attributes attributes;
  std::string text;  // inline content (ascii or base64)
};

// What the XML holds, before any data is decoded.
struct Piece {
  Attributes attributes;
  std::optional<DataArray> points;
  std::vector<DataArray> polys, strips;
};

struct Document {
  Attributes file;  // VTKFile's attributes
  std::vector<Piece> pieces;
  bool poly_data = false;
};

// --- the XML, through expat ---

class XmlReader {
 public:
  explicit XmlReader(const std::string& label) : label_(label) {}

  Document parse(std::string_view xml) {
    XML_Parser parser = XML_ParserCreate(nullptr);
    if (!parser) throw UserError(label_ + ": out of memory starting the XML parser");
    XML_SetUserData(parser, this);
    XML_SetElementHandler(parser, &XmlReader::start, &XmlReader::end);
    XML_SetCharacterDataHandler(parser, &XmlReader::characters);
    const bool parsed = XML_Parse(parser, xml.data(), int(xml.size()), 1) == XML_STATUS_OK;
    const std::string problem = parsed ? "" : XML_ErrorString(XML_GetErrorCode(parser));
    const auto line = XML_GetCurrentLineNumber(parser);
    XML_ParserFree(parser);
    if (!error_.empty()) throw UserError(label_ + ": " + error_);
    if (!parsed) {
      // Expat's own text may say it already: "not well-formed (invalid token)".
      constexpr std::string_view kSaid = "not well-formed";
      const std::string what = problem.starts_with(kSaid) ? "not well-formed XML" + problem.substr(kSaid.size())
                                                          : "not well-formed XML (" + problem + ")";
      throw_at_line(label_, std::size_t(line), what);
    }
    return std::move(document_);
  }

 private:
  static void start(void* self, const XML_Char* name, const XML_Char** attributes) {
    static_cast<XmlReader*>(self)->open(name, attributes);
  }
  static void end(void* self, const XML_Char* /*name*/) { static_cast<XmlReader*>(self)->close(); }
  static void characters(void* self, const XML_Char* text, int length) {
    auto* reader = static_cast<XmlReader*>(self);
    // The array's own text only, not that of elements inside it (VTK writes
    // an <InformationKey> with <Value>s into a DataArray, after its values).
    if (reader->array_ && reader->path_.size() == 5) reader->array_->text.append(text, std::size_t(length));
  }

  void open(std::string_view name, const XML_Char** raw) {
    Attributes attributes;
    for (std::size_t i = 0; raw[i] && raw[i + 1]; i += 2) attributes.emplace(raw[i], raw[i + 1]);
    path_.emplace_back(name);
    const std::size_t depth = path_.size();
    if (depth == 1) {
      if (name != "VTKFile") error_ = "expected a <VTKFile> element, found " + quoted(name);
      document_.file = std::move(attributes);
    } else if (depth == 2 && name == "PolyData") {
      document_.poly_data = true;
    } else if (depth == 3 && name == "Piece" && path_[1] == "PolyData") {
      document_.pieces.push_back({std::move(attributes), std::nullopt, {}, {}});
    } else if (depth == 5 && name == "DataArray" && path_[2] == "Piece" && path_[1] == "PolyData") {
      Piece& piece = document_.pieces.back();
      if (path_[3] == "Points") {
        if (piece.points) {
          error_ = "a piece's <Points> holds more than one DataArray";
        } else {
          piece.points = DataArray{std::move(attributes), {}};
          array_ = &*piece.points;
        }
      } else if (path_[3] == "Polys" || path_[3] == "Strips") {
        auto& arrays = path_[3] == "Polys" ? piece.polys : piece.strips;
        arrays.push_back({std::move(attributes), {}});
        array_ = &arrays.back();
      }
    }
  }

  void close() {
    if (path_.size() == 5) array_ = nullptr;
    path_.pop_back();
  }


  const std::string& label_;
  Document document_;
  std::vector<std::string> path_;
  DataArray* array_ = nullptr;
  std::string error_;  // the first problem; expat cannot be thrown through
};

// --- binary data: base64, headers, zlib ---

int base64_value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

// Base64 in groups of four characters, whitespace skipped. A group with
// padding ends a stream and the next group starts another: VTK's writers
// encode a header and its data as two streams, meshio sometimes as one.
// `max_bytes`: stop once that many bytes are decoded. Text that is not
// base64 sets `problem` (the caller names the file and the array).
std::vector<unsigned char> decode_base64(std::string_view text, std::size_t max_bytes, std::string& problem) {
  std::vector<unsigned char> bytes;
  bytes.reserve(std::min(max_bytes, text.size() / 4 * 3 + 3));
  std::array<int, 4> group{};
  std::size_t filled = 0, padding = 0;
  for (const char c : text) {
    if (bytes.size() >= max_bytes) break;
    if (is_space(c)) continue;
    if (c == '=') {
      if (filled < 2) {
        problem = "base64 padding out of place";
        return {};
      }
      ++padding;
      group[filled++] = 0;
    } else {
      const int value = base64_value(c);
      if (value < 0 || padding > 0) {
        problem = "not base64 data";
        return {};
      }
      group[filled++] = value;
    }
    if (filled < 4) continue;
    const std::uint32_t bits = std::uint32_t(group[0]) << 18 | std::uint32_t(group[1]) << 12 |
                               std::uint32_t(group[2]) << 6 | std::uint32_t(group[3]);
    const unsigned char decoded[3] = {static_cast<unsigned char>(bits >> 16), static_cast<unsigned char>(bits >> 8),
                                      static_cast<unsigned char>(bits)};
    bytes.insert(bytes.end(), decoded, decoded + 3 - padding);
    filled = padding = 0;
  }
  if (filled != 0 && bytes.size() < max_bytes) {
    problem = "base64 data ends inside a group";
    return {};
  }
  if (bytes.size() > max_bytes) bytes.resize(max_bytes);
  return bytes;
}

std::optional<ValueType> parse_vtp_type(std::string_view name) {
  static constexpr std::pair<std::string_view, ValueType> kNames[] = {
      {"Int8", ValueType::int8},     {"UInt8", ValueType::uint8},     {"Int16", ValueType::int16},
      {"UInt16", ValueType::uint16}, {"Int32", ValueType::int32},     {"UInt32", ValueType::uint32},
      {"Int64", ValueType::int64},   {"UInt64", ValueType::uint64},   {"Float32", ValueType::float32},
      {"Float64", ValueType::float64}};
  for (const auto& [known, type] : kNames) {
    if (name == known) return type;
  }
  return std::nullopt;
}

// --- the reader ---

class VtpReader {
 public:
  VtpReader(std::span<const char> bytes, const std::string& label) : bytes_(bytes), label_(label) {}

  PolygonSoup read() {
    const std::string_view all(bytes_.data(), bytes_.size());
    // The appended block may be raw bytes, which no XML parser takes: the
    // XML is everything before it, closed by hand; the block is kept aside.
    std::string xml;
    const std::size_t appended_at = appended_tag(all);
    if (appended_at == std::string_view::npos) {
      xml = std::string(all);
    } else {
      const std::size_t tag_end = all.find('>', appended_at);
      if (tag_end == std::string_view::npos) fail("the <AppendedData> tag never ends");
      const std::size_t marker = all.find('_', tag_end);
      if (marker == std::string_view::npos) fail("the appended data has no '_' marker");
      const std::size_t close = all.rfind("</AppendedData>");
      appended_ = all.substr(marker + 1, (close == std::string_view::npos || close < marker ? all.size() : close) -
                                             marker - 1);
      xml = std::string(all.substr(0, tag_end + 1)) + "</AppendedData></VTKFile>";
      appended_base64_ = attribute_in_tag(all.substr(appended_at, tag_end - appended_at), "encoding") == "base64";
    }
    const Document document = XmlReader(label_).parse(xml);
    read_file_attributes(document.file);
    if (!document.poly_data) fail("not a PolyData file (VTKFile type " + quoted(value_or(document.file, "type", "")) + ")");
    if (document.pieces.empty()) fail("the PolyData has no <Piece>");
    for (const Piece& piece : document.pieces) read_piece(piece);
    return std::move(soup_);
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const { throw UserError(label_ + ": " + problem); }

  static std::string value_or(const Attributes& attributes, std::string_view name, std::string fallback) {
    const auto found = attributes.find(name);
    return found == attributes.end() ? fallback : found->second;
  }

  // Where the <AppendedData> start tag is, outside comments, CDATA sections
  // and processing instructions (where the text "<AppendedData" is only
  // text); npos where there is none.
  static std::size_t appended_tag(std::string_view all) {
    static constexpr std::pair<std::string_view, std::string_view> kNotMarkup[] = {
        {"<!--", "-->"}, {"<![CDATA[", "]]>"}, {"<?", "?>"}};
    std::size_t at = 0;
    while ((at = all.find('<', at)) != std::string_view::npos) {
      bool skipped = false;
      for (const auto& [open, close] : kNotMarkup) {
        if (all.substr(at, open.size()) != open) continue;
        const std::size_t end = all.find(close, at + open.size());
        if (end == std::string_view::npos) return std::string_view::npos;  // the XML parse says what is wrong
        at = end + close.size();
        skipped = true;
        break;
      }
      if (skipped) continue;
      if (all.substr(at, 13) == "<AppendedData") return at;
      ++at;
    }
    return std::string_view::npos;
  }

  // An attribute of a start tag in raw text (the AppendedData tag, kept out of the XML parse).
  static std::string attribute_in_tag(std::string_view tag, std::string_view name) {
    const std::size_t at = tag.find(std::string(name) + "=");
    if (at == std::string_view::npos || at + name.size() + 2 > tag.size()) return "";
    const char quote = tag[at + name.size() + 1];
    const std::size_t end = tag.find(quote, at + name.size() + 2);
    if (end == std::string_view::npos) return "";
    return std::string(tag.substr(at + name.size() + 2, end - at - name.size() - 2));
  }

  void read_file_attributes(const Attributes& file) {
    const std::string order = value_or(file, "byte_order", "LittleEndian");
    if (order != "LittleEndian" && order != "BigEndian") fail("unknown byte_order " + quoted(order));
    big_endian_ = order == "BigEndian";
    const std::string header = value_or(file, "header_type", "UInt32");
    if (header != "UInt32" && header != "UInt64") fail("unknown header_type " + quoted(header));
    header_bytes_ = header == "UInt64" ? 8 : 4;
    const std::string compressor = value_or(file, "compressor", "");
    if (!compressor.empty() && compressor != "vtkZLibDataCompressor") {
      fail("compressor " + quoted(compressor) + " is not read (only vtkZLibDataCompressor)");
    }
    compressed_ = !compressor.empty();
  }

  std::size_t count_attribute(const Attributes& attributes, std::string_view name, const std::string& where) const {
    const std::string text = value_or(attributes, name, "0");
    const auto count = parse_integer(text);
    if (!count || *count < 0) fail(where + ": " + std::string(name) + " " + quoted(text) + " is not a count");
    return std::size_t(*count);
  }

  // One binary block at the start of `encoded` (base64 text when `base64`,
  // else raw bytes): a header, then the data, inflated where compressed.
  // The header must claim `expected_bytes` of data (the array's values),
  // checked before anything of that size is allocated.
  std::vector<unsigned char> block(std::string_view encoded, bool base64, std::uint64_t expected_bytes,
                                   const std::string& what) {
    // The bound on what the arrays may inflate to holds for the whole file:
    // pieces may all point at one appended block (40 pieces of a million
    // points on one block of zeros took 10.7 s and 1.6 GB to refuse).
    decoded_ += expected_bytes;
    if (decoded_ > kMaxInflation * bytes_.size() + kMaxInflation) {
      fail(what + ": the file's arrays would take " + plural(decoded_, "byte") + ", more than " +
           std::to_string(kMaxInflation) + " times its size");
    }
    const std::uint64_t available = base64 ? encoded.size() / 4 * 3 : encoded.size();
    // The first n bytes of the block, header included.
    block_extent_ = 0;
    const auto first_bytes = [&](std::uint64_t n) {
      if (n > available) fail(what + ": data ends before the " + plural(n, "byte") + " its header claims");
      // Of `encoded`, at least these were read: n bytes, or their base64
      // characters (whitespace and a second stream's padding aside).
      block_extent_ = std::max(block_extent_, base64 ? n / 3 * 4 : n);
      std::string problem;
      std::vector<unsigned char> bytes = base64 ? decode_base64(encoded, std::size_t(n), problem)
                                                : std::vector<unsigned char>(encoded.begin(), encoded.begin() +
                                                                                              std::ptrdiff_t(n));
      if (!problem.empty()) fail(what + ": " + problem);
      if (bytes.size() < n) fail(what + ": data ends before the " + plural(n, "byte") + " its header claims");
      return bytes;
    };
    const std::size_t h = header_bytes_;
    const auto header_value = [&](std::span<const unsigned char> bytes, std::size_t i) {
      return BinaryValues(bytes, h == 8 ? ValueType::uint64 : ValueType::uint32, big_endian_).header_count(i);
    };
    const auto claims = [&](std::uint64_t bytes) {
      if (bytes != expected_bytes) {
        fail(what + ": its header claims " + plural(bytes, "byte") + " where the array's values take " +
             std::to_string(expected_bytes));
      }
    };
    if (!compressed_) {
      claims(header_value(first_bytes(h), 0));
      std::vector<unsigned char> all = first_bytes(h + expected_bytes);
      all.erase(all.begin(), all.begin() + std::ptrdiff_t(h));
      return all;
    }
    // Compressed: the number of blocks, the block size, the last block's
    // size (0: a full one), each block's compressed size; then the blocks.
    const std::vector<unsigned char> counts = first_bytes(3 * h);
    const std::uint64_t blocks = header_value(counts, 0), block_size = header_value(counts, 1),
                        last_size = header_value(counts, 2);
    if (blocks > available / h) fail(what + ": its header claims " + plural(blocks, "block") + ", past the data");
    const std::vector<unsigned char> header = first_bytes((3 + blocks) * h);
    std::uint64_t compressed_total = 0;
    std::vector<std::uint64_t> sizes(blocks);
    for (std::size_t b = 0; b < blocks; ++b) {
      sizes[b] = header_value(header, 3 + b);
      if (sizes[b] > available) fail(what + ": block " + std::to_string(b) + " claims more bytes than the data holds");
      compressed_total += sizes[b];
    }
    if (blocks > 0 && (block_size == 0 || last_size > block_size)) fail(what + ": block sizes out of order");
    // The blocks of block_size: all but a partial last one. One partial
    // block may be far smaller than block_size (VTK's 32768 by default, for
    // an array of 48 bytes), so only full blocks are held against the data.
    const std::uint64_t full_blocks = blocks == 0 ? 0 : blocks - (last_size == 0 ? 0 : 1);
    if (full_blocks > 0 && block_size > expected_bytes / full_blocks) {
      fail(what + ": its header claims " + plural(full_blocks, "full block") + " of " + plural(block_size, "byte") +
           ", more than the array's values take (" + std::to_string(expected_bytes) + ")");
    }
    const std::uint64_t inflated = full_blocks * block_size + (blocks == 0 ? 0 : last_size);
    claims(inflated);
    if (inflated > kMaxInflation * compressed_total + kMaxInflation) {
      fail(what + ": " + plural(compressed_total, "compressed byte") + " cannot inflate to " +
           plural(inflated, "byte"));
    }
    const std::vector<unsigned char> data = first_bytes((3 + blocks) * h + compressed_total);
    std::vector<unsigned char> out(inflated);
    std::size_t in_at = (3 + blocks) * h, out_at = 0;
    for (std::size_t b = 0; b < blocks; ++b) {
      const std::uint64_t wanted = b + 1 == blocks && last_size != 0 ? last_size : block_size;
      uLongf produced = uLongf(wanted);
      if (uncompress(out.data() + out_at, &produced, data.data() + in_at, uLong(sizes[b])) != Z_OK ||
          produced != wanted) {
        fail(what + ": block " + std::to_string(b) + " does not inflate to its " + plural(wanted, "byte"));
      }
      in_at += std::size_t(sizes[b]);
      out_at += std::size_t(wanted);
    }
    return out;
  }

  // The appended bytes [begin, end) for one array. Arrays that share
  // bytes are refused: VTK's writers give each its own, and pieces that all
  // point at one uncompressed block stayed within the inflation bound yet
  // took 1.6 GB from a file of 2.4 MB.
  void claim_appended(std::uint64_t begin, std::uint64_t end, const std::string& what) {
    const auto after = appended_claims_.lower_bound(begin);
    const auto overlapped = after != appended_claims_.end() && after->first < end
                                ? after
                                : after != appended_claims_.begin() && std::prev(after)->second > begin
                                      ? std::prev(after)
                                      : appended_claims_.end();
    if (overlapped != appended_claims_.end()) {
      fail(what + ": its appended data (bytes " + std::to_string(begin) + " to " + std::to_string(end) +
           ") overlaps another array's (bytes " + std::to_string(overlapped->first) + " to " +
           std::to_string(overlapped->second) + "): each array has its own");
    }
    appended_claims_.emplace(begin, end);
  }

  // One DataArray's values (`expected` of them) as doubles or as indices.
  struct Values {
    std::vector<double> reals;
    std::vector<long long> integers;
  };
  Values values(const DataArray& array, std::size_t expected, bool integers, const std::string& what) {
    const auto type = parse_vtp_type(value_or(array.attributes, "type", ""));
    if (!type) fail(what + ": unknown type " + quoted(value_or(array.attributes, "type", "")));
    if (integers && (*type == ValueType::float32 || *type == ValueType::float64)) fail(what + ": not an integer type");
    const std::string format = value_or(array.attributes, "format", "ascii");
    Values out;
    if (format == "ascii") {
      if (expected > array.text.size() / 2 + 1) {
        fail(what + ": " + plural(expected, "value") + ", more than its " + plural(array.text.size(), "byte") + " can hold");
      }
      ByteCursor cursor(std::span<const char>(array.text.data(), array.text.size()));
      for (std::size_t i = 0; i < expected; ++i) {
        const auto token = cursor.next_token();
        if (!token) fail(what + ": ends after " + plural(i, "value") + " of " + std::to_string(expected));
        if (integers) {
          const auto value = parse_integer(*token);
          if (!value) fail(what + ": expected an integer, got " + quoted(*token));
          out.integers.push_back(*value);
        } else {
          const auto value = parse_real(*token);
          if (!value) fail(what + ": expected a number, got " + quoted(*token));
          out.reals.push_back(*value);
        }
      }
      // More values than the counts say (NumberOfPolys smaller than the
      // connectivity, or anything after the last value): the counts and
      // the data disagree, as the binary encodings refuse too.
      if (const auto extra = cursor.next_token()) {
        fail(what + ": more than its " + plural(expected, "value") + " (then " + quoted(*extra) + ")");
      }
      return out;
    }
    std::vector<unsigned char> bytes;
    const std::uint64_t expected_bytes = std::uint64_t(expected) * size_of(*type);
    if (format == "binary") {
      bytes = block(array.text, true, expected_bytes, what);
    } else if (format == "appended") {
      const std::size_t offset = count_attribute(array.attributes, "offset", what);
      if (offset > appended_.size()) fail(what + ": offset " + std::to_string(offset) + " is past the appended data");
      bytes = block(appended_.substr(offset), appended_base64_, expected_bytes, what);
      claim_appended(offset, offset + block_extent_, what);
    } else {
      fail(what + ": unknown format " + quoted(format));
    }
    const BinaryValues decoded(bytes, *type, big_endian_);
    if (decoded.count() != expected) {
      fail(what + ": " + plural(decoded.count(), "value") + " where " + std::to_string(expected) + " belong");
    }
    for (std::size_t i = 0; i < expected; ++i) {
      if (!integers) {
        out.reals.push_back(decoded.real(i));
        continue;
      }
      const auto value = decoded.integer(i);
      if (!value) fail(what + ": value " + std::to_string(i) + " is not an index");
      out.integers.push_back(*value);
    }
    return out;
  }

  // The DataArray of `arrays` with that Name.
  const DataArray& named(const std::vector<DataArray>& arrays, std::string_view name, const std::string& where) {
    for (const DataArray& array : arrays) {
      if (value_or(array.attributes, "Name", "") == name) return array;
    }
    fail(where + " has no DataArray named '" + std::string(name) + "'");
  }

  void read_piece(const Piece& piece) {
    const std::size_t first_vertex = soup_.vertices.size();
    const std::size_t points = count_attribute(piece.attributes, "NumberOfPoints", "<Piece>");
    if (points > 0) {
      if (!piece.points) fail("a piece with " + plural(points, "point") + " has no <Points> DataArray");
      if (count_attribute(piece.points->attributes, "NumberOfComponents", "<Points>") != 3) {
        fail("<Points> must have NumberOfComponents=\"3\"");
      }
      if (points > kMaxInflation * bytes_.size()) {
        fail("NumberOfPoints " + std::to_string(points) + " is more than the file can hold");
      }
      const Values xyz = values(*piece.points, 3 * points, false, "<Points>");
      for (std::size_t i = 0; i < points; ++i) {
        soup_.vertices.push_back({xyz.reals[3 * i], xyz.reals[3 * i + 1], xyz.reals[3 * i + 2]});
      }
    }
    read_cells(piece, piece.polys, "NumberOfPolys", "<Polys>", false, first_vertex, points);
    read_cells(piece, piece.strips, "NumberOfStrips", "<Strips>", true, first_vertex, points);
  }

  void read_cells(const Piece& piece, const std::vector<DataArray>& arrays, std::string_view count_name,
                  const std::string& where, bool strips, std::size_t first_vertex, std::size_t points) {
    const std::size_t cells = count_attribute(piece.attributes, count_name, "<Piece>");
    if (cells == 0) return;
    if (cells > kMaxInflation * bytes_.size()) {
      fail(std::string(count_name) + " " + std::to_string(cells) + " is more than the file can hold");
    }
    const std::vector<long long> ends = values(named(arrays, "offsets", where), cells, true, where + " offsets").integers;
    long long previous = 0;
    for (std::size_t c = 0; c < cells; ++c) {
      if (ends[c] < previous) fail(where + ": offsets decrease at cell " + std::to_string(c));
      previous = ends[c];
    }
    if (std::uint64_t(previous) > kMaxInflation * bytes_.size()) {
      fail(where + ": the offsets claim more indices than the file can hold");
    }
    const std::vector<long long> connectivity =
        values(named(arrays, "connectivity", where), std::size_t(previous), true, where + " connectivity").integers;
    // Indices are the piece's own: one outside it would silently take another
    // piece's point (or, shifted past the earlier pieces' points, overflow).
    for (const long long index : connectivity) {
      if (index < 0 || std::uint64_t(index) >= points) {
        fail(where + ": the point index " + std::to_string(index) + " is outside its piece's " +
             plural(points, "point"));
      }
    }
    const auto shift = static_cast<long long>(first_vertex);
    std::size_t begin = 0;
    for (std::size_t c = 0; c < cells; ++c) {
      const auto end = std::size_t(ends[c]);
      if (!strips) {
        for (std::size_t i = begin; i < end; ++i) soup_.face_vertices.push_back(connectivity[i] + shift);
        soup_.close_face();
      } else {
        for (std::size_t i = begin; i + 2 < end; ++i) {
          const long long a = connectivity[i] + shift, b = connectivity[i + 1] + shift, d = connectivity[i + 2] + shift;
          if (a == b || b == d || a == d) continue;  // joins two strips
          if ((i - begin) % 2 == 0) {
            soup_.add_triangle(a, b, d);
          } else {
            soup_.add_triangle(b, a, d);
          }
        }
      }
      begin = end;
    }
  }

  std::span<const char> bytes_;
  const std::string& label_;
  std::string_view appended_;
  bool appended_base64_ = false;
  bool big_endian_ = false;
  std::size_t header_bytes_ = 4;
  std::uint64_t decoded_ = 0;  // the bytes of every array's values so far
  std::uint64_t block_extent_ = 0;  // of the last block(): how far into its text it read
  std::map<std::uint64_t, std::uint64_t> appended_claims_;  // the appended bytes each array read: begin -> end
  bool compressed_ = false;
  PolygonSoup soup_;
};

}  // namespace

PolygonSoup read_vtp(std::span<const char> bytes, const std::string& label) { return VtpReader(bytes, label).read(); }

}  // namespace meshparticles
