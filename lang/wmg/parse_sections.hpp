// The section parsers of the WMG level-2 front end (internal): each starts at its section keyword
// and leaves the cursor after the section, or throws SyntaxError after reporting.
#pragma once

#include "lang/wmg/parser_cursor.hpp"
#include "lang/wmg/syntax.hpp"

namespace scenfuzz::wmg::detail {

Scenery parse_scenery(Cursor& cursor);
// One junction, from its ID to its last part (the scenery parser loops over them).
Junction parse_junction(Cursor& cursor);
Dynamics parse_dynamics(Cursor& cursor);
Environment parse_environment(Cursor& cursor);
TrafficModel parse_traffic_model(Cursor& cursor);

}  // namespace scenfuzz::wmg::detail
