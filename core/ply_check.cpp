#include "core/ply_check.h"

#include <algorithm>
#include <charconv>
#include <sstream>
#include <string_view>
#include <vector>

#include "core/error.h"

namespace rt {
namespace {

struct PlyProperty {
    bool list = false;
    int count_bytes = 0;  // a list's length: its type's bytes in a binary body
    int value_bytes = 0;  // one value (of the list, for a list)
    bool count_signed = false;
    bool value_signed = false, value_float = false;
    bool vertex_indices = false;  // a face's list of vertex indices: each must name a vertex
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

enum class Format { kAscii, kLittle, kBig };

struct Header {
    Format format = Format::kAscii;
    std::vector<PlyElement> elements;
    int lines = 0;               // the header's, end_header included
    std::uint64_t vertices = 0;  // the vertex element's count
};

// The bytes one value of a PLY type takes in a binary body (Assimp's names too).
int type_bytes(const std::string& type) {
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if (type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" ||
        type == "float32")
        return 4;
    if (type == "double" || type == "float64") return 8;
    return 1;  // char, uchar, int8, uint8
}

bool signed_type(const std::string& type) {
    return type == "char" || type == "short" || type == "int" || type == "int8" ||
           type == "int16" || type == "int32";
}

Header read_header(const std::string& file, std::istream& in) {
    Header h;
    std::string line;
    while (std::getline(in, line)) {
        ++h.lines;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line == "end_header") return h;
        std::istringstream words(line);
        std::string keyword, a, b, c, d;  // a list property: list COUNT_TYPE VALUE_TYPE NAME
        words >> keyword >> a >> b >> c >> d;
        if (keyword == "format")
            h.format = a == "ascii"               ? Format::kAscii
                       : a == "binary_big_endian" ? Format::kBig
                                                  : Format::kLittle;
        if (keyword == "element") {
            PlyElement e{a, 0, {}};
            const auto [end, ec] = std::from_chars(b.data(), b.data() + b.size(), e.count);
            if (ec == std::errc{} && end == b.data() + b.size()) h.elements.push_back(e);
            if (a == "vertex") h.vertices = e.count;
        }
        if (keyword == "property" && !h.elements.empty()) {
            PlyProperty p;
            p.list = a == "list";
            p.count_bytes = p.list ? type_bytes(b) : 0;
            p.count_signed = p.list && signed_type(b);
            const std::string& value_type = p.list ? c : a;
            p.value_bytes = type_bytes(value_type);
            p.value_signed = signed_type(value_type);
            p.value_float = value_type.find("float") != std::string::npos || value_type == "double";
            const std::string& name = p.list ? d : b;
            p.vertex_indices = p.list && h.elements.back().name == "face" &&
                               (name == "vertex_indices" || name == "vertex_index");
            h.elements.back().properties.push_back(p);
        }
    }
    if (h.lines == 0) throw Error(file, "header", "the file is empty");
    throw Error(file, "line " + std::to_string(h.lines),
                "the PLY header ends without its end_header line");
}

// Each element's instances take at least their values' bytes in binary, or a character
// and a separator per value in ASCII: a count beyond what the rest of the file can hold
// is refused before the body is read.
void check_counts(const std::string& file, const Header& h, std::uint64_t body_bytes,
                  std::uint64_t file_bytes) {
    std::uint64_t budget = body_bytes + 1;  // ASCII's last value may end the file unseparated
    for (const PlyElement& e : h.elements) {
        std::uint64_t least = 0;
        for (const PlyProperty& p : e.properties)
            least += h.format == Format::kAscii ? 2 : p.list ? p.count_bytes : p.value_bytes;
        if (least == 0) continue;
        if (e.count > budget / least)
            throw Error(file, "element " + e.name,
                        "the header declares " + std::to_string(e.count) +
                            ", more than the file's " + std::to_string(file_bytes) +
                            " bytes can hold");
        budget -= e.count * least;
    }
}

std::string ordinal(std::uint64_t i, const PlyElement& e) {
    return e.name + " " + std::to_string(i + 1) + " of the " + std::to_string(e.count);
}

std::string no_such_vertex(std::uint64_t i, const PlyElement& e, const std::string& index,
                           const Header& h) {
    return ordinal(i, e) + " names vertex " + index + ", not one of the " +
           std::to_string(h.vertices) + " (counted from 0)";
}

// A binary value of `bytes` bytes in the file's byte order, as a whole number (signed
// types sign-extended).
long long binary_integer(const unsigned char* at, int bytes, bool is_signed, Format format) {
    std::uint64_t bits = 0;
    for (int k = 0; k < bytes; ++k)
        bits = bits << 8 | at[format == Format::kBig ? k : bytes - 1 - k];
    if (is_signed && bytes < 8 && (bits >> (8 * bytes - 1)) != 0)
        bits |= ~std::uint64_t{0} << (8 * bytes);
    return static_cast<long long>(bits);
}

// Whether a word is a decimal number as PLY's ASCII body writes one (an optional sign,
// digits with an optional point, an optional exponent), or nan, inf or infinity in any
// case. A syntax check, not a conversion: Assimp converts; this only keeps it from
// taking a word for zero.
bool is_number(std::string_view w) {
    std::size_t i = 0;
    const auto digits = [&] {
        const std::size_t from = i;
        while (i < w.size() && w[i] >= '0' && w[i] <= '9') ++i;
        return i - from;
    };
    if (i < w.size() && (w[i] == '+' || w[i] == '-')) ++i;
    if (i < w.size() && ((w[i] | 0x20) == 'n' || (w[i] | 0x20) == 'i')) {
        std::string rest(w.substr(i));
        for (char& c : rest) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
        return rest == "nan" || rest == "inf" || rest == "infinity";
    }
    std::size_t mantissa = digits();
    if (i < w.size() && w[i] == '.') ++i, mantissa += digits();
    if (mantissa == 0) return false;
    if (i < w.size() && (w[i] == 'e' || w[i] == 'E')) {
        ++i;
        if (i < w.size() && (w[i] == '+' || w[i] == '-')) ++i;
        if (digits() == 0) return false;
    }
    return i == w.size();
}

// An ASCII body in memory, line by line, each split into its words at blanks.
class Lines {
  public:
    Lines(std::string_view body, int header_lines) : body_(body), number_(header_lines) {}

    // The next line with a word on it; false at the body's end.
    bool next(std::vector<std::string_view>& words) {
        words.clear();
        while (words.empty()) {
            if (at_ >= body_.size()) return false;
            std::size_t end = body_.find('\n', at_);
            if (end == std::string_view::npos) end = body_.size();
            ++number_;
            for (std::size_t i = at_; i < end;) {
                while (i < end && is_blank(body_[i])) ++i;
                const std::size_t from = i;
                while (i < end && !is_blank(body_[i])) ++i;
                if (i > from) words.push_back(body_.substr(from, i - from));
            }
            at_ = end + 1;
        }
        return true;
    }
    int number() const { return number_; }

  private:
    static bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

    std::string_view body_;
    std::size_t at_ = 0;
    int number_;
};

// An ASCII body: each instance on a line of its own (blank lines skipped), a list's
// length before its values, every value a number.
void check_ascii(const std::string& file, const Header& h, std::string_view body) {
    Lines lines(body, h.lines);
    std::vector<std::string_view> words;
    for (const PlyElement& e : h.elements) {
        for (std::uint64_t i = 0; i < e.count; ++i) {
            if (!lines.next(words))
                throw Error(file, "line " + std::to_string(lines.number() + 1),
                            "the file ends before " + ordinal(i, e) + " the header declares");
            const std::string where = "line " + std::to_string(lines.number());
            std::size_t next = 0;
            const auto take = [&] {
                if (next == words.size())
                    throw Error(file, where, ordinal(i, e) + " ends before its last value");
                const std::string_view w = words[next++];
                if (!is_number(w))
                    throw Error(file, where, "\"" + std::string(w) + "\" is not a number");
                return w;
            };
            for (const PlyProperty& p : e.properties) {
                const std::string_view first = take();
                if (!p.list) continue;
                std::uint64_t length = 0;
                const auto [end, ec] =
                    std::from_chars(first.data(), first.data() + first.size(), length);
                if (ec != std::errc{} || end != first.data() + first.size())
                    throw Error(
                        file, where,
                        ordinal(i, e) + ": \"" + std::string(first) + "\" is not a list's length");
                if (length > words.size() - next)
                    throw Error(file, where, ordinal(i, e) + " ends before its last value");
                for (std::uint64_t k = 0; k < length; ++k) {
                    const std::string_view w = take();
                    if (!p.vertex_indices) continue;
                    long long index = -1;
                    const auto [at, code] = std::from_chars(w.data(), w.data() + w.size(), index);
                    if (code != std::errc{} || at != w.data() + w.size() || index < 0 ||
                        static_cast<std::uint64_t>(index) >= h.vertices)
                        throw Error(file, where, no_such_vertex(i, e, std::string(w), h));
                }
            }
        }
    }
}

// A binary body: each instance's values back to back, a list's length (of its own type,
// in the file's byte order) before its values.
void check_binary(const std::string& file, const Header& h, std::string_view body) {
    const auto* at = reinterpret_cast<const unsigned char*>(body.data());
    const auto* const end = at + body.size();
    for (const PlyElement& e : h.elements) {
        std::uint64_t fixed = 0;  // the bytes of an instance without lists
        bool lists = false;
        for (const PlyProperty& p : e.properties) {
            if (p.list)
                lists = true;
            else
                fixed += static_cast<std::uint64_t>(p.value_bytes);
        }
        const auto ends = [&](std::uint64_t i) {
            return Error(file, "element " + e.name,
                         "the file ends in " + ordinal(i, e) + " the header declares");
        };
        if (!lists) {  // check_counts has kept count * fixed within the file's size
            if (e.count * fixed > static_cast<std::uint64_t>(end - at))
                throw ends(static_cast<std::uint64_t>(end - at) /
                           std::max<std::uint64_t>(fixed, 1));
            at += e.count * fixed;
            continue;
        }
        for (std::uint64_t i = 0; i < e.count; ++i) {
            for (const PlyProperty& p : e.properties) {
                if (!p.list) {
                    if (end - at < p.value_bytes) throw ends(i);
                    at += p.value_bytes;
                    continue;
                }
                if (end - at < p.count_bytes) throw ends(i);
                std::uint64_t length = 0;
                for (int k = 0; k < p.count_bytes; ++k) {
                    const int byte = h.format == Format::kBig ? k : p.count_bytes - 1 - k;
                    length = length << 8 | at[byte];
                }
                const bool negative =
                    p.count_signed &&
                    (at[h.format == Format::kBig ? 0 : p.count_bytes - 1] & 0x80u) != 0;
                at += p.count_bytes;
                if (negative)
                    throw Error(file, "element " + e.name,
                                ordinal(i, e) + ": a list of negative length");
                if (length > static_cast<std::uint64_t>(end - at) /
                                 static_cast<std::uint64_t>(p.value_bytes))
                    throw ends(i);
                if (p.vertex_indices && !p.value_float) {
                    for (std::uint64_t k = 0; k < length; ++k, at += p.value_bytes) {
                        const long long index =
                            binary_integer(at, p.value_bytes, p.value_signed, h.format);
                        if (index < 0 || static_cast<std::uint64_t>(index) >= h.vertices)
                            throw Error(file, "element " + e.name,
                                        no_such_vertex(i, e, std::to_string(index), h));
                    }
                } else {
                    at += length * static_cast<std::uint64_t>(p.value_bytes);
                }
            }
        }
    }
}

}  // namespace

void check_ply(const std::string& file, std::istream& in, std::uint64_t file_bytes) {
    const Header h = read_header(file, in);
    const auto at = in.tellg();
    const std::uint64_t header_bytes = at < 0 ? file_bytes : static_cast<std::uint64_t>(at);
    const std::uint64_t body_bytes = file_bytes - std::min(file_bytes, header_bytes);
    check_counts(file, h, body_bytes, file_bytes);
    std::string body(body_bytes, '\0');
    in.read(body.data(), static_cast<std::streamsize>(body.size()));
    body.resize(static_cast<std::size_t>(in.gcount()));
    if (h.format == Format::kAscii)
        check_ascii(file, h, body);
    else
        check_binary(file, h, body);
}

}  // namespace rt
