#include "vofdem/base/SceneFile.hpp"

#include <yaml.h>

#include <cstdio>
#include <memory>
#include <sstream>

namespace vofdem {

namespace {

std::string Where(const std::string &path, const yaml_mark_t &mark) {
  std::ostringstream s;
  s << path << ":" << mark.line + 1 << ":" << mark.column + 1;
  return s.str();
}

int CharacterAt(FILE *file, size_t index) {
  const long keep = std::ftell(file);
  int        c    = EOF;
  if (std::fseek(file, (long)index, SEEK_SET) == 0) c = std::fgetc(file);
  std::fseek(file, keep, SEEK_SET);
  return c;
}

bool CheckYaml(const std::string &path, FILE *file, std::string *message) {
  yaml_parser_t parser;
  if (!yaml_parser_initialize(&parser)) {
    *message = path + ": cannot initialise the YAML parser";
    return false;
  }
  yaml_parser_set_input_file(&parser, file);
  bool ok = true, seenRoot = false;
  int depth = 0;
  for (;;) {
    yaml_event_t event;
    if (!yaml_parser_parse(&parser, &event)) {
      // libyaml's "found character that cannot start any token" for a tab says neither "tab" nor why
      const bool tab = CharacterAt(file, parser.problem_mark.index) == '\t' || CharacterAt(file, parser.context_mark.index) == '\t';
      *message = Where(path, parser.problem_mark) + ": malformed YAML: " +
                 (tab ? std::string("a tab; YAML indents with spaces only") : std::string(parser.problem ? parser.problem : "parse error"));
      if (parser.context && !tab) *message += std::string(" ") + parser.context;
      ok = false;
      break;
    }
    const yaml_event_type_t type = event.type;
    if (depth == 0 && !seenRoot &&
        (type == YAML_SCALAR_EVENT || type == YAML_SEQUENCE_START_EVENT)) {
      *message = Where(path, event.start_mark) +
                 ": a scene must be a mapping of options (key: value), not a list or a scalar";
      ok = false;
    }
    if (type == YAML_MAPPING_START_EVENT || type == YAML_SEQUENCE_START_EVENT) {
      if (depth == 0) seenRoot = true;
      ++depth;
    }
    if (type == YAML_MAPPING_END_EVENT || type == YAML_SEQUENCE_END_EVENT) --depth;
    if (type == YAML_STREAM_END_EVENT && !seenRoot) {
      *message = path + ": the scene file is empty (no options in it)";
      ok = false;
    }
    yaml_event_delete(&event);
    if (!ok || type == YAML_STREAM_END_EVENT) break;
  }
  yaml_parser_delete(&parser);
  return ok;
}

}  // namespace

bool CheckSceneFile(const std::string &path, SceneFormat format, std::string *message) {
  std::unique_ptr<FILE, int (*)(FILE *)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) {
    *message = path + ": cannot open the scene file (missing or unreadable)";
    return false;
  }
  if (format == SceneFormat::Yaml) return CheckYaml(path, file.get(), message);
  return true;
}

}  // namespace vofdem
