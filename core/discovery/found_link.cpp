#include "discovery/found_link.h"

#include "io/can_transport.h"

namespace imudesk::discovery {

device::LinkRequest linkRequestFor(const FoundDevice &d)
{
    switch (d.link) {
    case FoundDevice::Link::Serial: {
        device::LinkRequest r = device::LinkRequest::serial(d.port, d.baud, d.family);
        if (d.address >= 0)
            r.deviceAddress = d.address;
        return r;
    }
    case FoundDevice::Link::Modbus: {
        device::ModbusOptions o;
        o.port = d.port;
        o.baud = d.baud;
        o.nodeId = d.address;
        o.kind = d.family == QLatin1String("hec495-modbus") ? protocol::modbus::DeviceKind::Hec495
                                                            : protocol::modbus::DeviceKind::Hipnuc;
        return device::LinkRequest::modbusDevice(o);
    }
    case FoundDevice::Link::Can: {
        device::CanSessionOptions o;
        const io::CanAddress address = io::CanAddress::parse(d.port);
        o.plugin = address.plugin;
        o.interfaceName = address.interfaceName;
        // The rate heard on the bus; an interface that takes none (virtualcan) is left as it is.
        o.bitrate = d.bitrateWhy.isEmpty() ? d.bitrate : 0;
        o.node = d.node;
        o.protocol = d.family == QLatin1String("j1939")     ? protocol::can::CanProtocol::J1939
                     : d.family == QLatin1String("canopen") ? protocol::can::CanProtocol::CanOpen
                                                            : protocol::can::CanProtocol::Hec495;
        return device::LinkRequest::canBus(o);
    }
    }
    return {};
}

} // namespace imudesk::discovery
