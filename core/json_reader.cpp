#include "core/json_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/error.h"

namespace rt {
namespace {

constexpr int kMaxNesting = 64;  // scenes nest a few levels; deeper is not a scene

struct TooDeep {};

std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] =
                std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1] ? 1u : 0u)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

std::string escape_pointer_token(std::string_view key) {
    std::string out;
    for (char c : key) {
        if (c == '~')
            out += "~0";
        else if (c == '/')
            out += "~1";
        else
            out += c;
    }
    return out;
}

std::string format_number(float x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

// nlohmann's messages start "[json.exception.parse_error.101] parse error at line 3,
// column 7: "; keep what follows.
std::string parse_error_detail(std::string message) {
    if (!message.empty() && message[0] == '[') message.erase(0, message.find("] ") + 2);
    const auto at = message.find(" at line ");
    const auto colon = message.find(": ");
    return at != std::string::npos && colon != std::string::npos ? message.substr(colon + 2)
                                                                 : message;
}

// Where `literal` stands as a number in the JSON text: outside strings, and not part of a
// longer token (the same digits in a name, or in a longer number, do not count).
std::size_t find_number(const std::string& text, const std::string& literal) {
    const auto in_number = [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '+' || c == '-';
    };
    bool in_string = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                in_string = false;
            continue;
        }
        if (c == '"') {
            in_string = true;
            continue;
        }
        if (text.compare(i, literal.size(), literal) == 0 && (i == 0 || !in_number(text[i - 1])) &&
            (i + literal.size() == text.size() || !in_number(text[i + literal.size()])))
            return i;
    }
    return std::string::npos;
}

std::string line_and_column(const std::string& text, std::size_t byte) {
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < std::min(byte, text.size()); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    // nlohmann reports the byte after the offending one
    return "line " + std::to_string(line) + ", column " +
           std::to_string(column > 1 ? column - 1 : 1);
}

}  // namespace

nlohmann::json parse_json_file(const std::filesystem::path& path) {
    const std::string file = path.string();
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw Error(file, "open", "is a directory, not a scene file");
    // Scene files are small (meshes live in OBJ files): a huge one is a mistake, and is
    // refused before it is read.
    constexpr std::uintmax_t kMaxSceneBytes = 64u << 20;
    const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
    if (!ec && bytes > kMaxSceneBytes)
        throw Error(
            file, "open",
            "is " + std::to_string(bytes >> 20) + " MiB; scene files are limited to 64 MiB");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(file, "open", "cannot open file (does it exist?)");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    if (text.find_first_not_of(" \t\r\n") == std::string::npos)
        throw Error(file, "line 1", "the file is empty");

    const auto limit_depth = [](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
        if (depth > kMaxNesting) throw TooDeep{};
        return true;
    };
    try {
        return nlohmann::json::parse(text, limit_depth, /*allow_exceptions=*/true,
                                     /*ignore_comments=*/true);
    } catch (const nlohmann::json::parse_error& e) {
        throw Error(file, line_and_column(text, e.byte), parse_error_detail(e.what()));
    } catch (const nlohmann::json::out_of_range& e) {
        // A number too large for a double: locate the literal nlohmann quotes.
        const std::string message = parse_error_detail(e.what());
        const auto open = message.find('\''), close = message.rfind('\'');
        const std::string literal = open < close ? message.substr(open + 1, close - open - 1) : "";
        const std::size_t at = literal.empty() ? std::string::npos : find_number(text, literal);
        throw Error(file, at == std::string::npos ? "(document)" : line_and_column(text, at + 1),
                    message);
    } catch (const TooDeep&) {
        throw Error(file, "(document)",
                    "nested more than " + std::to_string(kMaxNesting) + " levels deep");
    }
}

void JsonValue::fail(const std::string& what) const {
    throw Error(*file_, pointer_.empty() ? "(top level)" : pointer_, what);
}

std::string JsonValue::describe_type() const {
    if (json_->is_number()) return "the number " + json_->dump();
    if (json_->is_string()) return "the string " + json_->dump();
    return json_->type_name() +
           std::string(json_->is_array() || json_->is_object() ? "" : " value");
}

void JsonValue::keys(std::initializer_list<std::string_view> allowed) const {
    if (!json_->is_object()) fail("expected an object {...}, got " + describe_type());
    for (const auto& [key, value] : json_->items()) {
        if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
        std::string message = "unknown key \"" + key + "\"";
        std::string_view best;
        std::size_t best_distance = 3;  // suggest only close matches
        for (std::string_view candidate : allowed) {
            const std::size_t d = edit_distance(key, candidate);
            if (d < best_distance) best_distance = d, best = candidate;
        }
        if (!best.empty())
            message += " (did you mean \"" + std::string(best) + "\"?)";
        else {
            message += "; allowed here:";
            for (std::string_view candidate : allowed) message += " " + std::string(candidate);
        }
        throw Error(*file_, pointer_ + "/" + escape_pointer_token(key), message);
    }
}

bool JsonValue::has(std::string_view key) const {
    return json_->is_object() && json_->contains(key);
}

JsonValue JsonValue::operator[](std::string_view key) const {
    if (!json_->is_object()) fail("expected an object {...}, got " + describe_type());
    const auto it = json_->find(key);
    if (it == json_->end()) fail("missing required key \"" + std::string(key) + "\"");
    return JsonValue(*it, pointer_ + "/" + escape_pointer_token(key), *file_);
}

std::optional<JsonValue> JsonValue::find(std::string_view key) const {
    if (!has(key)) return std::nullopt;
    return (*this)[key];
}

std::vector<std::pair<std::string, JsonValue>> JsonValue::members() const {
    if (!json_->is_object()) fail("expected an object {...}, got " + describe_type());
    std::vector<std::pair<std::string, JsonValue>> out;
    for (const auto& [key, value] : json_->items())
        out.emplace_back(key, JsonValue(value, pointer_ + "/" + escape_pointer_token(key), *file_));
    return out;
}

std::vector<JsonValue> JsonValue::elements(std::size_t min_size, std::size_t max_size) const {
    if (!json_->is_array()) fail("expected an array [...], got " + describe_type());
    const std::size_t n = json_->size();
    if (n < min_size || n > max_size) {
        const std::string expected =
            min_size == max_size   ? std::to_string(min_size)
            : max_size == SIZE_MAX ? "at least " + std::to_string(min_size)
                                   : std::to_string(min_size) + " to " + std::to_string(max_size);
        fail("expected " + expected + " elements, got " + std::to_string(n));
    }
    std::vector<JsonValue> out;
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i)
        out.emplace_back((*json_)[i], pointer_ + "/" + std::to_string(i), *file_);
    return out;
}

double JsonValue::number_double() const {
    if (!json_->is_number()) fail("expected a number, got " + describe_type());
    const double x = json_->get<double>();
    if (!std::isfinite(x)) fail("is not a finite number");
    if (std::fabs(x) > std::numeric_limits<float>::max())
        fail("is too large (" + json_->dump() + ")");
    return x;
}

float JsonValue::number() const { return static_cast<float>(number_double()); }

glm::dvec3 JsonValue::dvector3() const {
    const auto e = elements(3, 3);
    return {e[0].number_double(), e[1].number_double(), e[2].number_double()};
}

float JsonValue::number_at_least(float lo) const {
    const float x = number();
    if (x < lo) fail("must be >= " + format_number(lo) + ", got " + format_number(x));
    return x;
}

float JsonValue::number_above(float lo) const {
    const float x = number();
    if (!(x > lo)) fail("must be > " + format_number(lo) + ", got " + format_number(x));
    return x;
}

float JsonValue::number_between(float lo, float hi) const {
    const float x = number();
    if (x < lo || x > hi)
        fail("must be between " + format_number(lo) + " and " + format_number(hi) + ", got " +
             format_number(x));
    return x;
}

int JsonValue::integer_between(int lo, int hi) const {
    if (!json_->is_number_integer()) fail("expected a whole number, got " + describe_type());
    const auto x = json_->get<long long>();
    if (x < lo || x > hi)
        fail("must be between " + std::to_string(lo) + " and " + std::to_string(hi) + ", got " +
             std::to_string(x));
    return static_cast<int>(x);
}

bool JsonValue::boolean() const {
    if (!json_->is_boolean()) fail("expected true or false, got " + describe_type());
    return json_->get<bool>();
}

std::string JsonValue::string() const {
    if (!json_->is_string()) fail("expected a string, got " + describe_type());
    return json_->get<std::string>();
}

vec3 JsonValue::vector3() const {
    const auto e = elements(3, 3);
    return {e[0].number(), e[1].number(), e[2].number()};
}

vec3 JsonValue::colour() const {
    if (json_->is_number()) return vec3(number_at_least(0.0f));
    const auto e = elements(3, 3);
    return {e[0].number_at_least(0.0f), e[1].number_at_least(0.0f), e[2].number_at_least(0.0f)};
}

}  // namespace rt
