#include "modbus_types.h"

namespace imudesk::device {

using protocol::modbus::DeviceKind;

int ModbusOptions::effectiveNodeId() const
{
    if (nodeId > 0)
        return nodeId;
    return kind == DeviceKind::Hec495 ? protocol::modbus::kHec495DefaultId : protocol::modbus::kHipnucDefaultId;
}

int ModbusOptions::effectiveBaud() const
{
    if (baud > 0)
        return baud;
    return kind == DeviceKind::Hec495 ? 9600 : 115200;
}

} // namespace imudesk::device
