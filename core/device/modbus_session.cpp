#include "modbus_session.h"

#include "device/modbus_family.h"

namespace imudesk::device {

ModbusSession::ModbusSession(QObject *parent, std::unique_ptr<io::Transport> transport)
    : Session(std::make_unique<ModbusFamily>(), std::move(transport), QStringLiteral("imudesk-modbus"),
              ModbusFamily::kLineIdleMs, parent)
{
    qRegisterMetaType<ModbusOptions>();
    qRegisterMetaType<ModbusScanOptions>();
    qRegisterMetaType<ModbusScanHit>();
    qRegisterMetaType<ModbusRegisterReply>();
    qRegisterMetaType<QList<ModbusScanHit>>();
    auto *f = static_cast<ModbusFamily *>(family());
    connect(f, &ModbusFamily::registersRead, this, &ModbusSession::registersRead);
    connect(f, &ModbusFamily::writeFinished, this, &ModbusSession::writeFinished);
    // Every family's requests end in requestEnded too, in the session's one id space.
    connect(this, &ModbusSession::registersRead, this, &ModbusSession::announceEnded<ModbusRegisterReply>);
    connect(this, &ModbusSession::writeFinished, this, &ModbusSession::announceEnded<ModbusRegisterReply>);
    connect(f, &ModbusFamily::nodeIdChanged, this, &ModbusSession::nodeIdChanged);
    connect(f, &ModbusFamily::baudChanged, this, &ModbusSession::baudChanged);
    connect(f, &ModbusFamily::pollRateChanged, this, &ModbusSession::pollRateChanged);
    connect(f, &ModbusFamily::scanProgress, this, &ModbusSession::scanProgress);
    connect(f, &ModbusFamily::scanFound, this, &ModbusSession::scanFound);
    connect(f, &ModbusFamily::scanFinished, this, &ModbusSession::scanFinished);
}

ModbusSession::~ModbusSession()
{
    cancelScan();
}

void ModbusSession::open(const ModbusOptions &options)
{
    m_kind = int(options.kind);
    inFamily<ModbusFamily>([options](ModbusFamily &f) { f.configure(options); });
    openLink(options.port, options.effectiveBaud());
}

void ModbusSession::close()
{
    cancelScan();
    Session::close();
}

QString ModbusSession::linkKind() const
{
    return m_kind.load() == int(protocol::modbus::DeviceKind::Hec495) ? QStringLiteral("HEC495 Modbus")
                                                                      : QStringLiteral("HiPNUC Modbus");
}

void ModbusSession::setPollRate(double hz)
{
    inFamily<ModbusFamily>([hz](ModbusFamily &f) { f.setPollRate(hz); });
}

quint64 ModbusSession::readRegisters(int start, int count)
{
    const quint64 id = takeRequestId();
    inFamily<ModbusFamily>([id, start, count](ModbusFamily &f) { f.readRegisters(id, start, count); });
    return id;
}

quint64 ModbusSession::writeRegister(int address, int value, bool verify)
{
    const quint64 id = takeRequestId();
    inFamily<ModbusFamily>([id, address, value, verify](ModbusFamily &f) { f.writeRegister(id, address, value, verify); });
    return id;
}

void ModbusSession::scan(const ModbusScanOptions &options)
{
    inFamily<ModbusFamily>([options](ModbusFamily &f) { f.scan(options); });
}

void ModbusSession::cancelScan()
{
    static_cast<ModbusFamily *>(family())->requestScanCancel();
}
double ModbusSession::maxPollRate(int baud, int registers, QSerialPort::Parity parity)
{
    if (baud <= 0 || registers <= 0)
        return 0;
    const double bits = parity == QSerialPort::NoParity ? 10.0 : 11.0;
    const double chars = 8.0 + (5.0 + 2.0 * registers) + 2 * 3.5;
    return 0.8 * double(baud) / (bits * chars);
}

QString ModbusSession::describeException(int code, const QString &where)
{
    switch (code) {
    case 0x01:
        return tr("ILLEGAL FUNCTION (01): the device does not support this request at %1.").arg(where);
    case 0x02:
        return tr("ILLEGAL DATA ADDRESS (02): %1 does not exist on this device or cannot be accessed this way "
                  "(write-only or read-only). Check the register map of the device's manual.")
            .arg(where);
    case 0x03:
        return tr("ILLEGAL DATA VALUE (03): the device refused the value or count for %1. Check the register's range.")
            .arg(where);
    case 0x04:
        return tr("SERVER DEVICE FAILURE (04): the device failed while handling %1. Reset it and try again.").arg(where);
    case 0x06:
        return tr("SERVER DEVICE BUSY (06): the device is busy; try %1 again later.").arg(where);
    default:
        return tr("Modbus exception %1 at %2.").arg(code).arg(where);
    }
}

} // namespace imudesk::device
