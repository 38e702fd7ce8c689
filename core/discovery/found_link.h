#pragma once
// The link request that connects a device a sweep found (discovery_result.h), as the window's
// "Connect" and the CLI open it: its port at the rate found, its family, address or node.
#include "discovery/discovery_result.h"
#include "links/link_opener.h"

namespace imudesk::discovery {

device::LinkRequest linkRequestFor(const FoundDevice &device);

} // namespace imudesk::discovery
