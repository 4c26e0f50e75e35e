// How the commands describe a collision of the ego: the contact in words, and whose fault it was
// with the numbers a user triages it by, in words and in JSON (`run`, `reconstruct`).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "oracle/responsibility.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// "collision at 2.35 s: ego front / npc1 rear at (10.2, 3.5)".
std::string describe_collision(const Trace& trace, const Collision& collision);

// "  responsibility: other: hit from behind while stopped" and the triage numbers on a line each.
std::string describe_responsibility(const Trace& trace, const CollisionResponsibility& r);

// The triage numbers: {"ego_speed", ..., "entry": {...}} (entry only when the other came into the
// ego's path).
nlohmann::json responsibility_json(const CollisionResponsibility& r);

}  // namespace scenfuzz
