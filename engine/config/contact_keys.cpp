#include "config/contact_keys.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace dem {

namespace {

// What a part of a law declares (contact/parameter.hpp); parts without keys declare nothing.
template <class Part>
constexpr auto parameters_of() {
  if constexpr (requires { Part::parameters; }) return Part::parameters;
  else return std::array<Parameter, 0>{};
}
template <class Part>
constexpr const char* switch_of() {
  if constexpr (requires { Part::switched_by; }) return Part::switched_by;
  else return nullptr;
}
template <class Part>
Part part_from(const ParameterValues& v) {
  if constexpr (requires { Part::from(v); }) return Part::from(v);
  else return Part{};
}
template <class Part>
void write_part(const Part& part, ParameterValues& v) {
  if constexpr (requires { part.write(v); }) part.write(v);
}

// One alternative of AnyContactLaw as the reader sees it: its law name, its keys (each once),
// the keys that switch its parts on, and for each key the switch of the part that reads it ("":
// a part always in the law).
struct LawEntry {
  std::size_t index;
  std::string law;
  std::vector<Parameter> keys;
  std::set<std::string> switches;
  std::map<std::string, std::string> switch_of_key;
};

template <class Law>
LawEntry entry_of(std::size_t index) {
  LawEntry e{index, Law::NormalLaw::law_name, {}, {}, {}};
  auto add = [&]<class Part>(std::type_identity<Part>) {
    const char* s = switch_of<Part>();
    for (const Parameter& p : parameters_of<Part>()) {
      if (e.switch_of_key.count(p.name)) continue;  // a shared key, declared once, read once
      e.keys.push_back(p);
      e.switch_of_key[p.name] = s ? s : "";
    }
    if (s) e.switches.insert(s);
  };
  add(std::type_identity<typename Law::NormalLaw>{});
  add(std::type_identity<typename Law::TangentialLaw>{});
  add(std::type_identity<typename Law::RollingLaw>{});
  return e;
}

// Every alternative of AnyContactLaw, in variant order.
const std::vector<LawEntry>& every_law() {
  static const std::vector<LawEntry> laws = []<std::size_t... I>(std::index_sequence<I...>) {
    return std::vector<LawEntry>{entry_of<std::variant_alternative_t<I, AnyContactLaw>>(I)...};
  }(std::make_index_sequence<std::variant_size_v<AnyContactLaw>>{});
  return laws;
}

// Alternative I of AnyContactLaw from the values of its keys.
template <std::size_t I>
AnyContactLaw law_from(const ParameterValues& v) {
  using Law = std::variant_alternative_t<I, AnyContactLaw>;
  return AnyContactLaw(std::in_place_index<I>, Law{part_from<typename Law::NormalLaw>(v), part_from<typename Law::TangentialLaw>(v),
                                                   part_from<typename Law::RollingLaw>(v)});
}
AnyContactLaw law_from(std::size_t index, const ParameterValues& v) {
  static const auto table = []<std::size_t... I>(std::index_sequence<I...>) {
    return std::array<AnyContactLaw (*)(const ParameterValues&), sizeof...(I)>{&law_from<I>...};
  }(std::make_index_sequence<std::variant_size_v<AnyContactLaw>>{});
  return table[index](v);
}

// The first complaint of the parts of alternative I about values their ranges allow.
template <class Part>
std::pair<const char*, std::string> problem_of(const ParameterValues& v) {
  if constexpr (requires { Part::problem(v); }) return Part::problem(v);
  else return {"", ""};
}
template <std::size_t I>
std::pair<const char*, std::string> problem_of_law(const ParameterValues& v) {
  using Law = std::variant_alternative_t<I, AnyContactLaw>;
  for (const auto& p : {problem_of<typename Law::NormalLaw>(v), problem_of<typename Law::TangentialLaw>(v),
                        problem_of<typename Law::RollingLaw>(v)})
    if (*p.first) return p;
  return {"", ""};
}
std::pair<const char*, std::string> problem_of(std::size_t index, const ParameterValues& v) {
  static const auto table = []<std::size_t... I>(std::index_sequence<I...>) {
    return std::array<std::pair<const char*, std::string> (*)(const ParameterValues&), sizeof...(I)>{&problem_of_law<I>...};
  }(std::make_index_sequence<std::variant_size_v<AnyContactLaw>>{});
  return table[index](v);
}

std::string format_number(double x) {  // as the range messages print numbers (default stream format)
  std::ostringstream s;
  s << x;
  return s.str();
}

bool contains(const std::vector<Parameter>& keys, const std::string& name) {
  for (const Parameter& p : keys)
    if (name == p.name) return true;
  return false;
}

// The key's doc, with the laws that read it when not every law does ("(law linear)"): from the
// alternatives, so a law added to AnyContactLaw is named beside the keys it shares.
std::string documented(const Parameter& p) {
  std::vector<std::string> names, readers;
  for (const LawEntry& e : every_law()) {
    if (std::find(names.begin(), names.end(), e.law) == names.end()) names.push_back(e.law);
    if (contains(e.keys, p.name) && std::find(readers.begin(), readers.end(), e.law) == readers.end()) readers.push_back(e.law);
  }
  if (readers.size() == names.size()) return p.doc;
  std::string doc = std::string(p.doc) + (readers.size() == 1 ? " (law " : " (laws ");
  for (std::size_t k = 0; k < readers.size(); ++k) doc += (k ? ", " : "") + readers[k];
  return doc + ")";
}

double read(Section& m, const Parameter& p) {
  const std::optional<double> def = p.required() ? std::nullopt : std::optional<double>(p.default_value);
  return m.number(p.name, p.unit, {p.min, p.max, p.min_open, p.max_open}, def, documented(p));
}

// The keys every law called `law` reads (its elastic constants), for messages.
std::vector<std::string> common_keys(const std::string& law) {
  std::vector<std::string> out;
  bool first = true;
  for (const LawEntry& e : every_law()) {
    if (e.law != law) continue;
    if (first) {
      for (const Parameter& p : e.keys)
        if (!e.switches.count(p.name)) out.push_back(p.name);
      first = false;
    } else {
      std::erase_if(out, [&](const std::string& k) { return !contains(e.keys, k); });
    }
  }
  return out;
}

// Records every key of every law in `dem keys` (Section records a key as it reads it): each is
// read from an empty mapping, and a required key's "missing" error dropped.
void document_every_key(const Section& material) {
  Section empty(YAML::Node(YAML::NodeType::Map), material.file(), material.path());
  for (const LawEntry& e : every_law())
    for (const Parameter& p : e.keys) try {
        read(empty, p);
      } catch (const ConfigError&) {
      }
}

}  // namespace

// The keys of every law called `law`, each once, in declaration order, with the switch of the part
// that reads each; and the switches of its parts.
struct NamedLaw {
  std::vector<Parameter> keys;
  std::map<std::string, std::string> switch_of_key;
  std::set<std::string> switches;
};
NamedLaw named_law(const std::string& law) {
  NamedLaw n;
  for (const LawEntry& e : every_law()) {
    if (e.law != law) continue;
    for (const Parameter& p : e.keys)
      if (!contains(n.keys, p.name)) n.keys.push_back(p), n.switch_of_key[p.name] = e.switch_of_key.at(p.name);
    n.switches.insert(e.switches.begin(), e.switches.end());
  }
  return n;
}

AnyContactLaw read_contact_law(Section& m) {
  document_every_key(m);
  std::vector<std::string> names;
  for (const LawEntry& e : every_law())
    if (std::find(names.begin(), names.end(), e.law) == names.end()) names.push_back(e.law);
  std::string doc = "contact law:";
  for (const std::string& n : names) {
    std::string keys;
    for (const std::string& k : common_keys(n)) keys += (keys.empty() ? "" : ", ") + k;
    doc += (n == names.front() ? " " : " or ") + n + " (" + keys + ")";
  }
  const std::string law = m.choice("law", names, names.front(), doc);
  const NamedLaw named = named_law(law);

  // A key that only laws of another name read is refused, naming them and what this law reads.
  for (const LawEntry& e : every_law())
    for (const Parameter& p : e.keys)
      if (!contains(named.keys, p.name) && m.has(p.name)) {
        std::string owners, own;
        for (const std::string& n : names)
          if (contains(named_law(n).keys, p.name)) owners += (owners.empty() ? "" : " or ") + n;
        for (const std::string& k : common_keys(law)) own += (own.empty() ? "" : " and ") + m.key_path(k);
        m.fail(p.name, "belongs to " + m.key_path("law") + ": " + owners + "; law " + law + " reads " + own);
      }

  // The switches (friction, rolling_friction, contact_damping) choose the alternative.
  ParameterValues values;
  for (const Parameter& p : named.keys)
    if (named.switches.count(p.name)) values[p.name] = read(m, p);
  const LawEntry* chosen = nullptr;
  for (const LawEntry& e : every_law()) {
    bool fits = e.law == law;
    for (const std::string& s : named.switches) fits = fits && ((values.at(s) > 0) == (e.switches.count(s) > 0));
    if (fits) chosen = &e;
  }
  if (!chosen) {
    std::string on, off, first_on;
    for (const std::string& s : named.switches) {
      std::string& list = values.at(s) > 0 ? on : off;
      list += (list.empty() ? "" : " and ") + m.key_path(s) + " = " + format_number(values.at(s));
      if (values.at(s) > 0 && first_on.empty()) first_on = s;
    }
    m.fail(first_on, "no law " + law + " combines " + on + (off.empty() ? "" : " with " + off) +
                         " (the engine is compiled for the laws of AnyContactLaw, contact/contact_law.hpp)");
  }
  // The chosen law's keys. A key of a part it does not have is an error, unless that key accepts it.
  for (const Parameter& p : named.keys) {
    if (named.switches.count(p.name)) continue;
    const std::string& s = named.switch_of_key.at(p.name);
    if (contains(chosen->keys, p.name)) {
      try {
        values[p.name] = read(m, p);
      } catch (const ConfigError& e) {
        // A key optional elsewhere: say why it is needed here.
        if (m.has(p.name) || s.empty()) throw;
        throw ConfigError(std::string(e.what()) + "; needed because " + m.key_path(s) + " = " + format_number(values.at(s)) + " > 0");
      }
    } else if (m.has(p.name)) {
      if (!p.accepted_when_off) m.fail(p.name, "is read only when " + s + " > 0; give both or neither");
      read(m, p);  // checked, unused
    }
  }
  if (const auto [key, what] = problem_of(chosen->index, values); *key) m.fail(key, what);
  return law_from(chosen->index, values);
}

void emit_contact_law(YAML::Emitter& out, const AnyContactLaw& any) {
  std::visit(
      [&](const auto& law) {
        using Law = std::decay_t<decltype(law)>;
        ParameterValues v;
        write_part(law.normal, v);
        write_part(law.tangential, v);
        write_part(law.rolling, v);
        out << YAML::Key << "law" << YAML::Value << Law::NormalLaw::law_name;
        // In the order the laws of this name declare them; a required switch (friction) is
        // written as 0 when its part is off.
        const NamedLaw named = named_law(Law::NormalLaw::law_name);
        for (const Parameter& p : named.keys) {
          const auto it = v.find(p.name);
          if (it != v.end()) out << YAML::Key << p.name << YAML::Value << it->second;
          else if (p.required() && named.switches.count(p.name)) out << YAML::Key << p.name << YAML::Value << 0.0;
        }
      },
      any);
}

}  // namespace dem
