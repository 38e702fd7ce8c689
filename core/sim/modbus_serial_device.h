#pragma once
// A simulated Modbus RTU device as bytes on a serial line (SimulatedSerialDevice), for the
// in-process session tests: the same ModbusDeviceModel as the pty server (modbus_rtu_server.h)
// behind RTU framing written here (protocol::modbus::RtuAdu). Requests to another node are
// ignored; a node-ID or baud write takes effect after its reply, as on the device.
//
// Faults a real bus shows, for tests: a reply with a broken CRC, and a 2-wire adapter that
// hears the host's own request back before the reply.
#include "sim/modbus_device_model.h"
#include "sim/simulated_serial_device.h"

#include <QByteArray>

namespace imudesk::sim {

class ModbusSerialDevice : public SimulatedSerialDevice {
public:
    explicit ModbusSerialDevice(ModbusSimOptions options = {});

    void receive(const uint8_t *data, size_t n) override;
    void advanceTo(int64_t nowUs) override;
    std::vector<SerialSegment> takeOutputSegments() override;
    int baud() const override { return m_baud; }
    std::string productName() const override { return m_model.productName(); }

    ModbusDeviceModel &model() { return m_model; }
    int nodeId() const { return m_nodeId; }
    // The next n replies go out with their CRC's last byte inverted.
    void corruptReplies(int n) { m_corrupt = n; }
    // Every request is heard back on the line before its reply.
    void setEcho(bool on) { m_echo = on; }
    uint64_t requestsSeen() const { return m_requests; }

private:
    void answer(const QByteArray &adu);
    void send(const QByteArray &bytes);

    ModbusDeviceModel m_model;
    int m_nodeId;
    int m_baud;
    int64_t m_nowUs = 0;
    QByteArray m_in;
    std::vector<SerialSegment> m_out;
    uint64_t m_chunk = 0;
    uint64_t m_requests = 0;
    int m_corrupt = 0;
    bool m_echo = false;
};

} // namespace imudesk::sim
