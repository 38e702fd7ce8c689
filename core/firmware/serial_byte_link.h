#pragma once
// ByteLink over a QSerialPort (8N1, no flow control), blocking. Create, use and destroy it
// in one thread (the update's worker thread); the port is opened by open().
#include "io/byte_link.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <memory>

QT_BEGIN_NAMESPACE
class QSerialPort;
QT_END_NAMESPACE

namespace imudesk::firmware {

class SerialByteLink : public ByteLink {
    Q_DECLARE_TR_FUNCTIONS(SerialByteLink)

public:
    explicit SerialByteLink(QString portName);
    ~SerialByteLink() override;

    bool open(int baud, QString *error) override;
    void close() override;
    bool isOpen() const override;
    bool write(const std::vector<uint8_t> &bytes, QString *error) override;
    bool read(std::vector<uint8_t> &out, int timeoutMs, QString *error) override;
    void clearInput() override;
    void sleepMs(int ms) override;
    int64_t nowUs() const override;

private:
    QString m_name;
    std::unique_ptr<QSerialPort> m_port;
    QElapsedTimer m_clock;
};

} // namespace imudesk::firmware
