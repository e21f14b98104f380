// NumberMapping.hpp: names to numbers or tables, with libyaml's event parser.
#include "vofdem/io/NumberMapping.hpp"

#include "vofdem/base/Options.hpp"

#include <yaml.h>

#include <cstdio>
#include <memory>

namespace vofdem {

bool ReadNumberMapping(const std::string &path, NumberMapping *out, std::string *message) {
  std::unique_ptr<FILE, int (*)(FILE *)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) {
    *message = path + ": cannot open the file";
    return false;
  }
  yaml_parser_t parser;
  if (!yaml_parser_initialize(&parser)) {
    *message = path + ": cannot initialise the YAML parser";
    return false;
  }
  yaml_parser_set_input_file(&parser, file.get());
  auto at = [&](const yaml_mark_t &m) { return path + ":" + std::to_string(m.line + 1); };

  NumberMapping result;
  bool          ok = true, done = false;
  int           depth = 0;  // 1: the top mapping, 2: a list, 3: a row of a table
  std::string   key;
  NumberEntry   entry;
  bool          flat = false, nested = false;  // the current list holds numbers / rows
  while (ok && !done) {
    yaml_event_t ev;
    if (!yaml_parser_parse(&parser, &ev)) {
      *message = at(parser.problem_mark) + ": malformed YAML: " + (parser.problem ? parser.problem : "parse error");
      ok       = false;
      break;
    }
    switch (ev.type) {
    case YAML_MAPPING_START_EVENT:
      if (depth != 0) *message = at(ev.start_mark) + ": '" + key + "': a value is a number or a table of numbers, not a mapping", ok = false;
      ++depth;
      break;
    case YAML_SEQUENCE_START_EVENT:
      if (depth == 0 || (depth == 1 && key.empty()) || depth >= 3) {
        *message = at(ev.start_mark) + ": a file of names and numbers takes at most a table (a list of rows) per name";
        ok       = false;
      } else if (depth == 1) {
        entry       = NumberEntry{};
        entry.line  = (int)ev.start_mark.line + 1;
        entry.table = true;
        flat = nested = false;
      } else if (flat) {
        *message = at(ev.start_mark) + ": '" + key + "': a list of numbers and rows mixed";
        ok       = false;
      } else {
        entry.rows.emplace_back();
        nested = true;
      }
      ++depth;
      break;
    case YAML_SEQUENCE_END_EVENT:
      --depth;
      if (depth == 1) {  // the end of a list: a flat list is one row
        for (const auto &r : entry.rows)
          if (r.size() != entry.rows[0].size() || r.empty()) {
            *message = path + ":" + std::to_string(entry.line) + ": '" + key + "': the rows of the table have different lengths";
            ok       = false;
          }
        if (entry.rows.empty()) *message = path + ":" + std::to_string(entry.line) + ": '" + key + "': an empty list", ok = false;
        result[key] = entry;
        key.clear();
      }
      break;
    case YAML_SCALAR_EVENT: {
      const std::string text((const char *)ev.data.scalar.value, ev.data.scalar.length);
      if (depth == 0) {
        *message = at(ev.start_mark) + ": expected a mapping of names to numbers (e.g. density: 8380)";
        ok       = false;
      } else if (depth == 1 && key.empty()) {
        key = text;
        if (result.count(key)) *message = at(ev.start_mark) + ": '" + key + "' is given twice", ok = false;
      } else {
        PetscReal v;
        if (!ParseReal(text, &v)) {
          *message = at(ev.start_mark) + ": '" + key + "': '" + text + "' is not a number";
          ok       = false;
        } else if (depth == 1) {
          NumberEntry e;
          e.line = (int)ev.start_mark.line + 1;
          e.rows = {{v}};
          result[key] = e;
          key.clear();
        } else if (depth == 2) {  // a flat list: one row
          if (nested) {
            *message = at(ev.start_mark) + ": '" + key + "': a list of numbers and rows mixed";
            ok       = false;
          }
          if (entry.rows.empty()) entry.rows.emplace_back();
          flat = true;
          entry.rows[0].push_back(v);
        } else {
          entry.rows.back().push_back(v);
        }
      }
      break;
    }
    case YAML_MAPPING_END_EVENT: --depth; break;
    case YAML_STREAM_END_EVENT: done = true; break;
    default: break;
    }
    yaml_event_delete(&ev);
  }
  yaml_parser_delete(&parser);
  if (ok) *out = std::move(result);
  return ok;
}

}  // namespace vofdem
