// A small JSON writer for the CLI's --json output: one object per call,
// keys in insertion order.
#ifndef LINEMAP_TOOLS_LINEMAP_JSON_H_
#define LINEMAP_TOOLS_LINEMAP_JSON_H_

#include <cstdint>
#include <string>
#include <vector>

namespace linemap::cli {

std::string JsonString(const std::string& text);  // quoted and escaped
std::string JsonNumber(double value);             // shortest round-trip form; null if not finite

class JsonObject {
 public:
  JsonObject& Add(const std::string& key, double value);
  JsonObject& Add(const std::string& key, std::int64_t value);
  JsonObject& Add(const std::string& key, std::uint64_t value);
  JsonObject& Add(const std::string& key, int value) { return Add(key, std::int64_t{value}); }
  JsonObject& Add(const std::string& key, bool value);
  JsonObject& Add(const std::string& key, const char* value);
  JsonObject& Add(const std::string& key, const std::string& value);
  JsonObject& Add(const std::string& key, const std::vector<double>& values);
  // `json` is already valid JSON text (a nested object or array).
  JsonObject& AddRaw(const std::string& key, const std::string& json);

  std::string str() const { return "{" + body_ + "}"; }

 private:
  void Key(const std::string& key);
  std::string body_;
};

}  // namespace linemap::cli

#endif  // LINEMAP_TOOLS_LINEMAP_JSON_H_
