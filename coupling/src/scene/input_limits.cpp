#include "coupling/scene/input_limits.hpp"

#include <algorithm>
#include <vector>

namespace coupling {

namespace {

// One open object or array while scanning: enough to name the JSON path of the place being scanned.
struct OpenContainer {
  bool is_object = false;
  bool expecting_key = false;  // objects: the next string is a key
  std::string key;             // objects: the key of the current member (as written, shortened)
  std::size_t index = 0;       // arrays: the index of the current element
};

// ".key" or "[index]".
std::string component(const OpenContainer& container) {
  std::string text(container.is_object ? "." : "[");
  text += container.is_object ? container.key : std::to_string(container.index);
  if (!container.is_object) text += ']';
  return text;
}

// "notes[0][0]...": the path of the value about to be opened inside `open`. A path hundreds of levels long is
// shortened to its first and last components, with the number of levels left out in between.
std::string path_of(const std::vector<OpenContainer>& open) {
  constexpr std::size_t head = 8, tail = 4;
  std::string path;
  for (std::size_t level = 0; level < open.size(); ++level) {
    if (open.size() > head + tail && level == head) {
      path += "<... " + std::to_string(open.size() - head - tail) + " levels ...>";
      level = open.size() - tail - 1;
      continue;
    }
    path += component(open[level]);
  }
  if (!path.empty() && path.front() == '.') path.erase(0, 1);
  return path;
}

std::string depth_message(const std::vector<OpenContainer>& open, std::size_t max_depth) {
  const std::string path = path_of(open);
  return (path.empty() ? std::string("(top level)") : path) + ": nested deeper than " + std::to_string(max_depth) +
         " levels of objects and arrays (at most " + std::to_string(max_depth) +
         " allowed: " + std::string(max_nesting_reason) + ")";
}

// Skips the string starting after the opening quote at `i`; returns the index of the closing quote (or the end).
std::size_t end_of_string(std::string_view text, std::size_t i) {
  for (; i < text.size(); ++i) {
    if (text[i] == '\\') {
      ++i;  // the escaped character, whatever it is
    } else if (text[i] == '"') {
      break;
    }
  }
  return i;
}

}  // namespace

std::optional<std::string> nesting_depth_fault(std::string_view text, std::size_t max_depth) {
  std::vector<OpenContainer> open;  // never more than max_depth + 1: the scan stops at the first fault
  for (std::size_t i = 0; i < text.size(); ++i) {
    switch (text[i]) {
      case '"': {
        const std::size_t end = end_of_string(text, i + 1);
        if (!open.empty() && open.back().is_object && open.back().expecting_key) {
          open.back().key = std::string(text.substr(i + 1, std::min<std::size_t>(end - i - 1, 40)));
          open.back().expecting_key = false;
        }
        i = end;
        break;
      }
      case '{':
      case '[':
        if (open.size() == max_depth) return depth_message(open, max_depth);
        open.push_back(OpenContainer{text[i] == '{', text[i] == '{', {}, 0});
        break;
      case '}':
      case ']':
        if (!open.empty()) open.pop_back();  // unbalanced brackets are the parser's to report
        break;
      case ',':
        if (!open.empty()) {
          if (open.back().is_object) {
            open.back().expecting_key = true;
          } else {
            ++open.back().index;
          }
        }
        break;
      default: break;
    }
  }
  return std::nullopt;
}

}  // namespace coupling
