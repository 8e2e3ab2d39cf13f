#include "core/json_reader.h"

#include <regex>
#include <set>

namespace ssr {

using files::fail;
using files::q;

namespace {

using json = nlohmann::json;

// Finds the first duplicate key (nlohmann keeps the last one silently), and a string or key that
// holds a NUL ("\u0000": a file name would end there, "a.obj\u0000.png" opening a.obj), in a
// SAX pass of its own:
// nlohmann 3.11.2's parse() with a callback rescans the enclosing array after every object,
// quadratic in the array's length (a 3 MB file of boxes ran for over 10 minutes; found while
// fuzzing).
struct DuplicateKeyFinder : nlohmann::json_sax<json> {
  std::vector<std::set<std::string>> seen;  // the keys of each open object
  std::string duplicate;
  bool nul = false;
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t& s) override {
    nul = s.find('\0') != string_t::npos;
    return !nul;
  }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override {
    seen.emplace_back();
    return true;
  }
  bool key(string_t& k) override {
    nul = k.find('\0') != string_t::npos;
    if (!nul && !seen.back().insert(k).second) duplicate = k;
    return duplicate.empty() && !nul;  // stops at the first one
  }
  bool end_object() override {
    seen.pop_back();
    return true;
  }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
    return false;
  }
};

}  // namespace

nlohmann::json parse_json_object(const std::string& text, const std::string& label) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) fail(label + " is empty");
  json j;
  std::string duplicate;
  bool nul = false;
  try {
    j = json::parse(text, nullptr, /*allow_exceptions=*/true, /*ignore_comments=*/true);
    DuplicateKeyFinder finder;  // only after a successful parse: no errors left to report
    json::sax_parse(text, &finder, json::input_format_t::json, /*strict=*/true,
                    /*ignore_comments=*/true);
    duplicate = finder.duplicate;
    nul = finder.nul;
  } catch (const json::parse_error& e) {
    const std::string what = e.what();
    static const std::regex re(R"(at line (\d+), column (\d+): (.*)$)");
    std::smatch m;
    if (std::regex_search(what, m, re))
      fail(label + " has a JSON syntax error at line " + m[1].str() +
           ", column " + (m[2].str() == "0" ? std::string("1") : m[2].str()) + ": " + m[3].str());
    fail(label + " has a JSON syntax error near byte " + std::to_string(e.byte));
  } catch (const json::exception& e) {
    // Not a parse_error but still bad input: a number beyond double's range throws
    // out_of_range.406 (found by fuzzing). Drop the "[json.exception.*] " prefix.
    std::string what = e.what();
    if (const std::size_t end = what.find("] "); end != std::string::npos) what.erase(0, end + 2);
    fail(label + " cannot be read: " + what);
  }
  if (nul) fail(label + " has a string with a NUL character (\\u0000) in it");
  if (!duplicate.empty()) fail(label + " has the key " + q(duplicate) + " twice");
  if (!j.is_object()) fail(label + " must hold a JSON object");
  return j;
}

}  // namespace ssr
