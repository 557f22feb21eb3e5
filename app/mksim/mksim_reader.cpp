#include "app/mksim/mksim_reader.hpp"

#include <muParser.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "app/case/expression.hpp"
#include "app/case/node_reader.hpp"
#include "hydro/data_file.hpp"

namespace heavesim::mksim {

const char* joint_type_name(JointType type) {
  switch (type) {
    case JointType::revolute: return "revolute";
    case JointType::spherical: return "spherical";
    case JointType::translational: return "translational";
    case JointType::universal: return "universal";
    case JointType::cylindrical: return "cylindrical";
  }
  return "?";
}

int joint_equation_count(JointType type) {
  // Haug (1989) §9.2-9.3: spherical 3 (coincident points), universal 4 (+ the two
  // axes perpendicular), cylindrical 4 (two axes parallel: 2, the point on the line: 2),
  // revolute 5 (spherical + axes parallel), translational 5 (cylindrical + no relative
  // rotation about the axis).
  switch (type) {
    case JointType::spherical: return 3;
    case JointType::universal:
    case JointType::cylindrical: return 4;
    case JointType::revolute:
    case JointType::translational: return 5;
  }
  return 0;
}

std::string with_time_named(const std::string& expression, const std::string& time_name) {
  std::string result;
  std::size_t i = 0;
  const auto is_word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  while (i < expression.size()) {
    if (!is_word(expression[i])) {
      result += expression[i++];
      continue;
    }
    std::size_t end = i;
    while (end < expression.size() && is_word(expression[end])) ++end;
    const std::string word = expression.substr(i, end - i);
    std::string lowered = word;
    std::transform(lowered.begin(), lowered.end(), lowered.begin(), [](unsigned char c) { return std::tolower(c); });
    // A word starting with a digit is a number ("1e5"), never the time.
    result += lowered == "time" && !std::isdigit(static_cast<unsigned char>(word[0])) ? time_name : word;
    i = end;
  }
  return result;
}

Eigen::Matrix3d frame_axes(const PointTriple& par) {
  const Eigen::Vector3d z = (par.z_point - par.origin).normalized();
  const Eigen::Vector3d to_x = par.x_point - par.origin;
  const Eigen::Vector3d x = (to_x - to_x.dot(z) * z).normalized();
  Eigen::Matrix3d axes;
  axes << x, z.cross(x), z;
  return axes;
}

namespace {

// The largest model file read: a model of thousands of bodies is well below it.
constexpr std::uintmax_t max_model_bytes = std::uintmax_t{16} << 20;

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

enum class TokenKind { word, number, punct, end };

struct Token {
  TokenKind kind = TokenKind::end;
  std::string text;
  SourceLocation location;
  std::size_t offset = 0;  // into the text
  std::size_t end_offset = 0;
  std::string describe() const {
    if (kind == TokenKind::end) return "the end of the file";
    return "'" + text + "'";
  }
};

/// Splits the text into words (letters, digits, _), numbers and punctuation, skipping
/// white space and `//` comments; keeps each token's line and column (1-based, bytes).
class Lexer {
 public:
  Lexer(const std::string& text, std::string file) : text_(text), file_(std::move(file)) {
    for (std::size_t i = 0; i < text_.size(); ++i)
      if (text_[i] == '\n') line_starts_.push_back(i + 1);
  }

  SourceLocation location_at(std::size_t offset) const {
    // The last line start at or before offset: its index is the line, the rest the column.
    const auto next_line = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
    const std::size_t line = static_cast<std::size_t>(next_line - line_starts_.begin());
    return {file_, static_cast<int>(line), static_cast<int>(offset - *(next_line - 1)) + 1};
  }

  const Token& peek() {
    if (!peeked_) {
      next_ = scan();
      peeked_ = true;
    }
    return next_;
  }
  Token take() {
    Token token = peek();
    peeked_ = false;
    return token;
  }

  /// The raw text from the current position to the `}` that closes the statement (at
  /// parenthesis depth 0), for a driver's expression; the `}` is left to be read.
  Token raw_until_brace() {
    peeked_ = false;
    skip_blank();
    Token token;
    token.kind = TokenKind::word;
    token.offset = position_;
    token.location = location_at(position_);
    int depth = 0;
    while (position_ < text_.size()) {
      const char c = text_[position_];
      if (c == '(') ++depth;
      if (c == ')') --depth;
      if ((c == '}' || c == ';') && depth <= 0) break;
      if (c == '\n' || (c == '/' && position_ + 1 < text_.size() && text_[position_ + 1] == '/')) break;
      ++position_;
    }
    std::size_t end = position_;
    while (end > token.offset && std::isspace(static_cast<unsigned char>(text_[end - 1]))) --end;
    token.text = text_.substr(token.offset, end - token.offset);
    token.end_offset = end;
    return token;
  }

  const std::string& file() const { return file_; }

 private:
  void skip_blank() {
    while (position_ < text_.size()) {
      const char c = text_[position_];
      if (std::isspace(static_cast<unsigned char>(c))) {
        ++position_;
      } else if (c == '/' && position_ + 1 < text_.size() && text_[position_ + 1] == '/') {
        while (position_ < text_.size() && text_[position_] != '\n') ++position_;
      } else {
        break;
      }
    }
  }

  Token scan() {
    skip_blank();
    Token token;
    token.offset = position_;
    token.location = location_at(position_);
    if (position_ >= text_.size()) {
      token.end_offset = position_;
      return token;
    }
    const auto is_word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    const char c = text_[position_];
    if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && position_ + 1 < text_.size() &&
                                                        std::isdigit(static_cast<unsigned char>(text_[position_ + 1])))) {
      // A number runs over digits, '.', an exponent and its sign, and any letters glued
      // to it (so that "1.2.3" or "3x" is one token the parser reports whole).
      token.kind = TokenKind::number;
      std::size_t end = position_;
      while (end < text_.size()) {
        const char d = text_[end];
        const bool exponent_sign = (d == '+' || d == '-') && (text_[end - 1] == 'e' || text_[end - 1] == 'E');
        if (!(is_word(d) || d == '.' || exponent_sign)) break;
        ++end;
      }
      token.text = text_.substr(position_, end - position_);
      position_ = end;
    } else if (is_word(c)) {
      token.kind = TokenKind::word;
      std::size_t end = position_;
      while (end < text_.size() && is_word(text_[end])) ++end;
      token.text = text_.substr(position_, end - position_);
      position_ = end;
    } else {
      token.kind = TokenKind::punct;
      token.text = std::string(1, c);
      ++position_;
    }
    token.end_offset = position_;
    return token;
  }

  const std::string& text_;
  std::string file_;
  std::vector<std::size_t> line_starts_{0};  // offset of each line's first byte
  std::size_t position_ = 0;
  bool peeked_ = false;
  Token next_;
};

std::string join(const std::vector<std::string>& words) {
  std::string text;
  for (std::size_t i = 0; i < words.size(); ++i) text += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + words[i];
  return text;
}

std::string suggest(const std::string& found, const std::vector<std::string>& candidates, const std::string& expected) {
  const std::string suggestion = closest_match(found, candidates);
  return suggestion.empty() ? expected : "'" + suggestion + "' (did you mean it?); " + expected;
}

/// The parser: one function per rule of the grammar (docs/mksim-format.md).
class Parser {
 public:
  Parser(const std::string& text, const std::string& file) : text_(text), lexer_(text, file) {}

  Model parse() {
    check_text();
    model_.file = lexer_.file();
    Token model_word = lexer_.take();
    if (model_word.kind != TokenKind::word || lower(model_word.text) != "model")
      fail(model_word, "model", "MODEL <name>, the first word of an MKSim model");
    model_.location = model_word.location;
    model_.name = name(lexer_.take(), "model", "the model's name");
    bool have_system = false;
    for (;;) {
      const Token token = lexer_.take();
      if (token.kind == TokenKind::end)
        fail(token, "model " + model_.name, "ENDMODEL closing the model opened at " + model_.location.to_string());
      if (token.kind != TokenKind::word) fail(token, "model " + model_.name, statement_expectation());
      const std::string word = lower(token.text);
      if (word == "endmodel") break;
      if (word == "system") {
        if (have_system) fail(token, "SYSTEM", "one SYSTEM block (a second one is here)");
        have_system = true;
        parse_system(token);
      } else if (word == "body") {
        parse_body();
      } else if (word == "triad") {
        parse_triad();
      } else if (word == "driver") {
        parse_driver();
      } else if (joint_types().count(word)) {
        parse_joint(token, joint_types().at(word));
      } else if (lexer_.peek().kind == TokenKind::word && lower(lexer_.peek().text) == "joint") {
        fail(token, "joint",
             suggest(lower(token.text), {"revolute", "spherical", "translational", "universal", "cylindrical"},
                     "a joint type: revolute, spherical, translational, universal or cylindrical"));
      } else {
        std::vector<std::string> words{"system", "body", "triad", "driver", "endmodel"};
        for (const auto& [type, unused] : joint_types()) words.push_back(type);
        fail(token, "model " + model_.name, suggest(lower(token.text), words, statement_expectation()));
      }
      skip_semicolon();
    }
    const Token after = lexer_.take();
    if (after.kind != TokenKind::end) fail(after, "ENDMODEL", "nothing after ENDMODEL (only comments)");
    if (!have_system) fail(model_.location, "model " + model_.name, "no SYSTEM block", "a SYSTEM block with the ending time");
    resolve();
    return std::move(model_);
  }

 private:
  static const std::map<std::string, JointType>& joint_types() {
    static const std::map<std::string, JointType> types{{"revolute", JointType::revolute},
                                                        {"spherical", JointType::spherical},
                                                        {"translational", JointType::translational},
                                                        {"translation", JointType::translational},
                                                        {"universal", JointType::universal},
                                                        {"cylindrical", JointType::cylindrical}};
    return types;
  }
  static std::string statement_expectation() {
    return "a statement: SYSTEM, BODY, triad, revolute|spherical|translational|universal|cylindrical joint, "
           "driver, or ENDMODEL";
  }

  [[noreturn]] void fail(const SourceLocation& where, const std::string& path, const std::string& found,
                         const std::string& expected) const {
    throw InputError(where, path, found, expected);
  }
  [[noreturn]] void fail(const Token& token, const std::string& path, const std::string& expected) const {
    throw InputError(token.location, path, token.describe(), expected);
  }

  /// An empty file and a binary one are refused before any token is read.
  void check_text() const {
    const auto blank = std::all_of(text_.begin(), text_.end(), [](unsigned char c) { return std::isspace(c); });
    if (text_.empty() || blank)
      fail(lexer_.location_at(0), "", text_.empty() ? "an empty file" : "a file of only white space",
           "an MKSim model: MODEL <name> ... ENDMODEL");
    for (std::size_t i = 0; i < text_.size(); ++i) {
      const unsigned char c = static_cast<unsigned char>(text_[i]);
      if ((c < 0x20 && c != '\n' && c != '\r' && c != '\t' && c != '\f') || c == 0x7f)
        fail(lexer_.location_at(i), "", fmt::format("the byte 0x{:02X} (a binary file?)", c),
             "the text of an MKSim model");
    }
  }

  std::string name(const Token& token, const std::string& path, const std::string& what) const {
    if (token.kind != TokenKind::word || std::isdigit(static_cast<unsigned char>(token.text[0])))
      fail(token, path, what + " (letters, digits and _, not starting with a digit)");
    return token.text;
  }

  void expect(const std::string& punct, const std::string& path, const std::string& expected) {
    const Token token = lexer_.take();
    if (token.kind != TokenKind::punct || token.text != punct) fail(token, path, expected);
  }

  void skip_semicolon() {
    if (lexer_.peek().kind == TokenKind::punct && lexer_.peek().text == ";") lexer_.take();
  }

  double number(const std::string& path) {
    Token token = lexer_.take();
    std::string text;
    if (token.kind == TokenKind::punct && (token.text == "-" || token.text == "+")) {
      const Token digits = lexer_.take();
      if (digits.kind != TokenKind::number || digits.offset != token.end_offset) fail(digits, path, "a number");
      text = token.text == "-" ? "-" : "";
      token.text += digits.text;
      token.kind = TokenKind::number;
      text += digits.text;
    } else {
      text = token.text;
    }
    if (token.kind != TokenKind::number) fail(token, path, "a number");
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
      fail(token, path, "a finite decimal number (e.g. -3, 0.5, 1e-11)");
    return value;
  }

  Eigen::Vector3d vector(const std::string& path) {
    const std::string expected = "a point (x, y, z)";
    expect("(", path, expected);
    Eigen::Vector3d v;
    for (int i = 0; i < 3; ++i) {
      v[i] = number(path);
      if (i < 2) expect(",", path, "',' and the next coordinate of " + expected);
    }
    expect(")", path, "')' closing " + expected);
    return v;
  }

  PointTriple triple(const std::string& path) {
    PointTriple par;
    par.location = lexer_.peek().location;
    expect("{", path, "{(origin), (a point on z), (a point on x)}");
    par.origin = vector(path);
    expect(",", path, "',' and a point on the z axis");
    par.z_point = vector(path);
    expect(",", path, "',' and a point on the x axis");
    par.x_point = vector(path);
    expect("}", path, "'}' closing the three points of par");
    // Degenerate axes: scale-aware, so that a model in mm is judged as one in m.
    const double scale = std::max({1.0, par.origin.norm(), par.z_point.norm(), par.x_point.norm()});
    const Eigen::Vector3d to_z = par.z_point - par.origin, to_x = par.x_point - par.origin;
    if (to_z.norm() <= 1e-9 * scale)
      fail(par.location, path, "a point on z equal to the origin (no z axis)", "a point on the z axis away from the origin");
    const double sine = to_x.norm() <= 1e-9 * scale ? 0.0 : to_z.normalized().cross(to_x.normalized()).norm();
    if (sine < 1e-6)
      fail(par.location, path,
           to_x.norm() <= 1e-9 * scale ? "a point on x equal to the origin" : "a point on x that lies on the z axis",
           "a point off the z axis, giving the x axis");
    return par;
  }

  /// The words of an item's key up to '=' ("center of gravity"), lower case; a flag item
  /// (no '=') ends at a separator or '}'.
  std::pair<std::string, Token> item_key(const std::string& path, const std::string& expected) {
    const Token first = lexer_.take();
    if (first.kind != TokenKind::word) fail(first, path, expected);
    std::string key = lower(first.text);
    while (lexer_.peek().kind == TokenKind::word) key += " " + lower(lexer_.take().text);
    return {key, first};
  }

  bool at_equals() { return lexer_.peek().kind == TokenKind::punct && lexer_.peek().text == "="; }

  void expect_equals(const std::string& path, const std::string& key) {
    expect("=", path, "'=' after '" + key + "'");
  }

  /// Separators between items: ',' or ';', optional (the seed's SYSTEM line omits one).
  /// Returns false at the closing '}'.
  bool next_item(const std::string& path, const Token& opening, bool triad_items = false) {
    while (lexer_.peek().kind == TokenKind::punct && (lexer_.peek().text == "," || lexer_.peek().text == ";")) lexer_.take();
    const Token& next = lexer_.peek();
    if (next.kind == TokenKind::punct && next.text == "}") {
      lexer_.take();
      return false;
    }
    // A statement's first word inside a block means its '}' is missing.
    const bool statement = next.kind == TokenKind::word && (lower(next.text) == "endmodel" || lower(next.text) == "body" ||
                                                            (lower(next.text) == "triad" && !triad_items) ||
                                                            lower(next.text) == "driver" ||
                                                            lower(next.text) == "system" || joint_types().count(lower(next.text)));
    if (next.kind == TokenKind::end || statement)
      fail(next, path, "'}' closing the block opened at " + opening.location.to_string());
    return true;
  }

  Token open_block(const std::string& path) {
    const Token token = lexer_.take();
    if (token.kind != TokenKind::punct || token.text != "{") fail(token, path, "'{' opening the block");
    return token;
  }

  void declare(const std::string& name_text, const SourceLocation& where, const std::string& path) {
    const auto [it, inserted] = names_.emplace(name_text, where);
    if (!inserted)
      fail(where, path, "the name '" + name_text + "' again",
           "a name not used before (it names something at " + it->second.to_string() +
               "; bodies, triads, joints and drivers share one name space)");
  }

  /// The start of a named statement (BODY, triad, joint, driver): its name, declared in
  /// the one name space, and the '{' of its block. `statement` is what errors call it
  /// before the name is known, `noun` what the name names, `kind` the path's prefix.
  struct NamedBlock {
    Token name_token;
    std::string name, path;
    Token opening;
  };
  NamedBlock named_block(const std::string& statement, const std::string& noun, const std::string& kind) {
    NamedBlock block{lexer_.take(), "", "", Token{}};
    block.name = name(block.name_token, statement, "the " + noun + "'s name");
    block.path = kind + " " + block.name;
    declare(block.name, block.name_token.location, block.path);
    block.opening = open_block(block.path);
    return block;
  }

  /// An item key the statement does not have: the did-you-mean among `keys`.
  [[noreturn]] void unknown_item(const Token& first, const std::string& path, const std::string& key,
                                 const std::vector<std::string>& keys, const std::string& statement) const {
    const std::string expected = "a " + statement + " item: " + join(keys);
    fail(first.location, path, "'" + key + "'", suggest(key, keys, expected));
  }

  void parse_system(const Token& keyword) {
    SystemSettings& system = model_.system;
    system.location = keyword.location;
    const std::string path = "SYSTEM";
    const Token opening = open_block(path);
    const std::map<std::string, std::optional<double> SystemSettings::*> numbers{
        {"starting time", &SystemSettings::starting_time},   {"ending time", &SystemSettings::ending_time},
        {"print interval", &SystemSettings::print_interval}, {"nr tolerance", &SystemSettings::nr_tolerance},
        {"assembly tolerance", &SystemSettings::assembly_tolerance}};
    std::vector<std::string> keys{"kinematic analysis"};
    for (const auto& [key, unused] : numbers) keys.push_back(key);
    bool kinematic = false;
    while (next_item(path, opening)) {
      const auto [key, first] = item_key(path, "a SYSTEM item: " + join(keys));
      if (key == "kinematic analysis" && !at_equals()) {
        kinematic = true;
        continue;
      }
      const auto member = numbers.find(key);
      if (member == numbers.end())
        unknown_item(first, path, key, keys, "SYSTEM");
      const std::string item_path = path + "." + key;
      expect_equals(item_path, key);
      const Token value_token = lexer_.peek();
      const double value = number(item_path);
      const bool time = key == "starting time";
      if (!time && !(value > 0.0))
        fail(value_token.location, item_path, fmt::format("{}", value), "a positive number");
      system.*(member->second) = value;
    }
    if (!kinematic) fail(keyword.location, path, "no KINEMATIC ANALYSIS", "KINEMATIC ANALYSIS (MKSim's only analysis)");
    if (!system.ending_time) fail(keyword.location, path, "no ending time", "ending time = <s>");
    if (*system.ending_time <= system.starting_time.value_or(0.0))
      fail(keyword.location, path + ".ending time", fmt::format("{} s", *system.ending_time),
           fmt::format("an ending time after the starting time {} s", system.starting_time.value_or(0.0)));
  }

  void parse_body() {
    const auto [name_token, body_name, path, opening] = named_block("BODY", "body", "BODY");
    Body body;
    body.name = body_name;
    body.location = name_token.location;
    const std::vector<std::string> keys{"ground", "center of gravity", "par"};
    while (next_item(path, opening)) {
      const auto [key, first] = item_key(path, "a BODY item: " + join(keys));
      if (key == "ground" && !at_equals()) {
        body.ground = true;
        continue;
      }
      if (key != "center of gravity" && key != "par")
        unknown_item(first, path, key, keys, "BODY");
      const std::string item_path = path + "." + key;
      expect_equals(item_path, key);
      if (key == "par") body.par = triple(item_path);
      else body.center_of_gravity = vector(item_path);
    }
    if (body.ground) {
      for (const Body& other : model_.bodies)
        if (other.ground)
          fail(name_token.location, path, "a second ground body (the first is '" + other.name + "')", "one ground body");
    } else {
      if (body.name == "ground")
        fail(name_token.location, path, "a moving body named 'ground'",
             "another name: heavesim's ground is the body flagged { ground }");
      if (!body.center_of_gravity) fail(name_token.location, path, "no center of gravity", "center of gravity = (x, y, z)");
      if (!body.par) fail(name_token.location, path, "no par", "par = {(origin), (a point on z), (a point on x)}");
    }
    check_origin(body.center_of_gravity, body.par, path, "center of gravity");
    model_.bodies.push_back(std::move(body));
  }

  /// The par triple repeats the origin; both must say the same.
  void check_origin(const std::optional<Eigen::Vector3d>& origin, const std::optional<PointTriple>& par,
                    const std::string& path, const std::string& origin_key) const {
    if (!origin || !par) return;
    const double scale = std::max(1.0, origin->norm());
    if ((par->origin - *origin).norm() > 1e-9 * scale)
      fail(par->location, path + ".par",
           fmt::format("a first point ({}, {}, {}) away from the {} ({}, {}, {})", par->origin.x(), par->origin.y(),
                       par->origin.z(), origin_key, origin->x(), origin->y(), origin->z()),
           "the par triple's first point equal to the " + origin_key);
  }

  void parse_triad() {
    const auto [name_token, triad_name, path, opening] = named_block("triad", "triad", "triad");
    Triad triad;
    triad.name = triad_name;
    triad.location = name_token.location;
    const std::vector<std::string> keys{"associated body", "origin", "par"};
    while (next_item(path, opening)) {
      const auto [key, first] = item_key(path, "a triad item: " + join(keys));
      if (std::find(keys.begin(), keys.end(), key) == keys.end())
        unknown_item(first, path, key, keys, "triad");
      const std::string item_path = path + "." + key;
      expect_equals(item_path, key);
      if (key == "par") {
        triad.par = triple(item_path);
      } else if (key == "origin") {
        triad.origin = vector(item_path);
      } else {
        const Token body_token = lexer_.take();
        triad.body = name(body_token, item_path, "a body's name");
        triad.body_location = body_token.location;
      }
    }
    if (triad.body.empty()) fail(name_token.location, path, "no associated body", "associated body = <body>");
    if (!triad.par) fail(name_token.location, path, "no par", "par = {(origin), (a point on z), (a point on x)}");
    if (!triad.origin) triad.origin = triad.par->origin;
    check_origin(triad.origin, triad.par, path, "origin");
    model_.triads.push_back(std::move(triad));
  }

  void parse_joint(const Token& type_token, JointType type) {
    Joint joint;
    joint.type = type;
    const Token joint_word = lexer_.take();
    if (joint_word.kind != TokenKind::word || lower(joint_word.text) != "joint")
      fail(joint_word, type_token.text, "the word 'joint' after the joint type");
    const auto [name_token, joint_name, path, opening] =
        named_block("joint", "joint", std::string(joint_type_name(type)) + " joint");
    joint.name = joint_name;
    joint.location = name_token.location;
    int count = 0;
    while (next_item(path, opening, true)) {
      const auto [key, first] = item_key(path, "triad = <triad>");
      if (key != "triad") fail(first.location, path, "'" + key + "'", suggest(key, {"triad"}, "triad = <triad>"));
      if (count == 2) fail(first.location, path, "a third triad", "two triads, the joint's two frames");
      expect_equals(path + ".triad", key);
      const Token triad_token = lexer_.take();
      joint.triad_names[count] = name(triad_token, path + ".triad", "a triad's name");
      joint.triad_locations[count] = triad_token.location;
      ++count;
    }
    if (count < 2)
      fail(name_token.location, path, fmt::format("{} triad{}", count, count == 1 ? "" : "s"),
           "two triads: triad = <on one body>, triad = <on the other>");
    model_.joints.push_back(std::move(joint));
  }

  void parse_driver() {
    const auto [name_token, driver_name, path, opening] = named_block("driver", "driver", "driver");
    Driver driver;
    driver.name = driver_name;
    driver.location = name_token.location;
    const std::string expected = "<body or triad>.<x|y|z> = <expression of TIME>";
    const Token target = lexer_.take();
    driver.target = name(target, path, expected);
    driver.target_location = target.location;
    const Token dot = lexer_.take();
    if (dot.kind != TokenKind::punct || dot.text != ".") fail(dot, path, "'.' and a coordinate: " + expected);
    const Token axis = lexer_.take();
    const std::string axis_name = lower(axis.text);
    if (axis.kind != TokenKind::word || (axis_name != "x" && axis_name != "y" && axis_name != "z"))
      fail(axis, path, "the coordinate x, y or z (world axes)");
    driver.axis = axis_name[0] - 'x';
    expect_equals(path + "." + driver.target + "." + axis_name, driver.target + "." + axis_name);
    const Token expression = lexer_.raw_until_brace();
    if (expression.text.empty()) fail(expression, path, "an expression of TIME, e.g. 8 + 3*sin(TIME)");
    driver.expression = expression.text;
    driver.expression_location = expression.location;
    check_expression(expression, path);
    const Token closing = lexer_.take();
    if (closing.kind != TokenKind::punct || closing.text != "}")
      fail(closing, path, "'}' closing the driver opened at " + opening.location.to_string() + " (one motion per driver)");
    model_.drivers.push_back(std::move(driver));
  }

  /// muParser parses the expression with TIME defined (and the functions of every case
  /// expression); a rejection is reported at its column in the file.
  void check_expression(const Token& expression, const std::string& path) const {
    mu::Parser parser;
    define_case_functions(parser);
    double time = model_.system.starting_time.value_or(0.0);
    parser.DefineVar("TIME", &time);
    try {
      parser.SetExpr(with_time_named(expression.text, "TIME"));  // same length: columns stay
      const double value = parser.Eval();
      (void)value;
    } catch (const mu::Parser::exception_type& e) {
      const std::size_t position = std::min<std::size_t>(static_cast<std::size_t>(std::max(0, e.GetPos())), expression.text.size());
      fail(lexer_.location_at(expression.offset + position), path,
           "'" + expression.text + "': " + e.GetMsg(),
           "an expression of TIME that muParser accepts (e.g. 8 + 3*sin(TIME))");
    }
  }

  /// Names to indices: triads on bodies, joints on triads, drivers on bodies or triads.
  void resolve() {
    std::map<std::string, std::size_t> bodies, triads;
    std::vector<std::string> body_names, triad_names;
    for (std::size_t i = 0; i < model_.bodies.size(); ++i) {
      bodies[model_.bodies[i].name] = i;
      body_names.push_back(model_.bodies[i].name);
      if (model_.bodies[i].ground) model_.ground = i;
    }
    for (std::size_t i = 0; i < model_.triads.size(); ++i) {
      triads[model_.triads[i].name] = i;
      triad_names.push_back(model_.triads[i].name);
    }
    const auto ground = std::find_if(model_.bodies.begin(), model_.bodies.end(), [](const Body& b) { return b.ground; });
    if (ground == model_.bodies.end())
      fail(model_.location, "model " + model_.name, "no ground body", "one BODY <name> { ground }");
    for (Triad& triad : model_.triads) {
      const auto body = bodies.find(triad.body);
      if (body == bodies.end())
        fail(triad.body_location, "triad " + triad.name + ".associated body", "'" + triad.body + "'",
             suggest(triad.body, body_names, "a body declared with BODY"));
      triad.body_index = body->second;
    }
    for (Joint& joint : model_.joints) {
      const std::string path = std::string(joint_type_name(joint.type)) + " joint " + joint.name;
      for (int k = 0; k < 2; ++k) {
        const auto triad = triads.find(joint.triad_names[k]);
        if (triad == triads.end())
          fail(joint.triad_locations[k], path + ".triad", "'" + joint.triad_names[k] + "'",
               suggest(joint.triad_names[k], triad_names, "a triad declared with triad"));
        joint.triads[k] = triad->second;
      }
      const Triad& a = model_.triads[joint.triads[0]];
      const Triad& b = model_.triads[joint.triads[1]];
      if (a.body_index == b.body_index)
        fail(joint.triad_locations[1], path + ".triad",
             "triads '" + a.name + "' and '" + b.name + "' both on body '" + a.body + "'",
             "triads on two different bodies");
    }
    for (Driver& driver : model_.drivers) {
      const std::string path = "driver " + driver.name;
      if (const auto body = bodies.find(driver.target); body != bodies.end()) {
        driver.body_index = body->second;
        driver.point.setZero();  // the body's reference point: its centre of gravity
      } else if (const auto triad = triads.find(driver.target); triad != triads.end()) {
        driver.body_index = model_.triads[triad->second].body_index;
        driver.point = *model_.triads[triad->second].origin;
      } else {
        std::vector<std::string> names = body_names;
        names.insert(names.end(), triad_names.begin(), triad_names.end());
        fail(driver.target_location, path, "'" + driver.target + "'",
             suggest(driver.target, names, "a body or a triad, whose point the driver moves"));
      }
      if (model_.bodies[driver.body_index].ground)
        fail(driver.target_location, path, "a driver on the ground body '" + model_.bodies[driver.body_index].name + "'",
             "a moving body or a triad on one (the ground does not move)");
    }
  }

  const std::string& text_;
  Lexer lexer_;
  Model model_;
  std::map<std::string, SourceLocation> names_;
};

}  // namespace

Model parse_model(const std::string& text, const std::string& file) { return Parser(text, file).parse(); }

Model read_model_file(const std::string& path) {
  if (const std::string problem = hydro::unreadable_file(path, max_model_bytes); !problem.empty())
    throw InputError({path, 0, 0}, "", problem, "a readable MKSim model file (.mks)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, 0}, "", "a file that cannot be opened", "a readable MKSim model file (.mks)");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_model(text.str(), path);
}

}  // namespace heavesim::mksim
