#include "modbus_session.h"

#include "device/modbus_worker.h"

namespace imudesk::device {

ModbusSession::ModbusSession(QObject *parent) : DeviceLink(parent)
{
    qRegisterMetaType<ModbusOptions>();
    qRegisterMetaType<ModbusScanOptions>();
    qRegisterMetaType<ModbusScanHit>();
    qRegisterMetaType<ModbusRegisterReply>();
    qRegisterMetaType<QList<ModbusScanHit>>();

    m_thread.setObjectName(QStringLiteral("imudesk-modbus"));
    m_worker = new ModbusWorker(store());
    m_worker->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);

    connect(m_worker, &ModbusWorker::stateChanged, this, [this](SessionState s, const QString &detail) { setState(s, detail); });
    connect(m_worker, &ModbusWorker::identityChanged, this, &ModbusSession::identityChanged);
    connect(m_worker, &ModbusWorker::statsUpdated, this, &ModbusSession::statsUpdated);
    connect(m_worker, &ModbusWorker::errorOccurred, this, &ModbusSession::errorOccurred);
    connect(m_worker, &ModbusWorker::registersRead, this, &ModbusSession::registersRead);
    connect(m_worker, &ModbusWorker::writeFinished, this, &ModbusSession::writeFinished);
    connect(m_worker, &ModbusWorker::nodeIdChanged, this, &ModbusSession::nodeIdChanged);
    connect(m_worker, &ModbusWorker::baudChanged, this, &ModbusSession::baudChanged);
    connect(m_worker, &ModbusWorker::pollRateChanged, this, &ModbusSession::pollRateChanged);
    connect(m_worker, &ModbusWorker::scanProgress, this, &ModbusSession::scanProgress);
    connect(m_worker, &ModbusWorker::scanFound, this, &ModbusSession::scanFound);
    connect(m_worker, &ModbusWorker::scanFinished, this, &ModbusSession::scanFinished);
    m_thread.start();
}

ModbusSession::~ModbusSession()
{
    m_worker->requestScanCancel();
    QMetaObject::invokeMethod(m_worker, &ModbusWorker::close, Qt::BlockingQueuedConnection);
    m_thread.quit();
    m_thread.wait();
}

void ModbusSession::open(const ModbusOptions &options)
{
    m_kind = int(options.kind);
    QMetaObject::invokeMethod(m_worker, [w = m_worker, options] { w->open(options); }, Qt::QueuedConnection);
}

void ModbusSession::close()
{
    m_worker->requestScanCancel();
    QMetaObject::invokeMethod(m_worker, &ModbusWorker::close, Qt::QueuedConnection);
}

QString ModbusSession::linkKind() const
{
    return m_kind.load() == int(protocol::modbus::DeviceKind::Hec495) ? QStringLiteral("HEC495 Modbus")
                                                                      : QStringLiteral("HiPNUC Modbus");
}

void ModbusSession::setPollRate(double hz)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, hz] { w->setPollRate(hz); }, Qt::QueuedConnection);
}

quint64 ModbusSession::readRegisters(int start, int count)
{
    const quint64 id = m_nextId++;
    QMetaObject::invokeMethod(m_worker, [w = m_worker, id, start, count] { w->readRegisters(id, start, count); },
                              Qt::QueuedConnection);
    return id;
}

quint64 ModbusSession::writeRegister(int address, int value, bool verify)
{
    const quint64 id = m_nextId++;
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker, id, address, value, verify] { w->writeRegister(id, address, value, verify); },
        Qt::QueuedConnection);
    return id;
}

void ModbusSession::scan(const ModbusScanOptions &options)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, options] { w->scan(options); }, Qt::QueuedConnection);
}

void ModbusSession::cancelScan()
{
    m_worker->requestScanCancel();
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
