#pragma once
// The contact law's keys of a scene's `material` mapping: which law, and its constants.
#include <yaml-cpp/yaml.h>

#include "config/yaml_section.hpp"
#include "contact/contact_law.hpp"

namespace dem {

// Reads material.law and the keys of that law from `material`; a key of another law, or a
// combination the engine does not have, is a ConfigError naming the keys.
AnyContactLaw read_contact_law(Section& material);
// Writes the law's keys, as read, into the resolved scene's material mapping (an open YAML map).
void emit_contact_law(YAML::Emitter& out, const AnyContactLaw& law);

}  // namespace dem
