#include "operator_input.h"

#include <QCoreApplication>
#include <QMetaObject>
#include <QObject>
#include <QPointer>

#include <thread>

#include <windows.h>

namespace imudesk::cli {

// Windows has no notifier for a console or pipe handle: a thread blocks in ReadFile and hands
// each chunk to the owner's thread through its event loop. At exit the thread is detached: it
// may still wait for a line that never comes, and the process ends around it.
class OperatorInput::Reader {
public:
    explicit Reader(OperatorInput &owner)
    {
        m_receiver = new QObject;
        QPointer<QObject> receiver(m_receiver);
        OperatorInput *target = &owner;
        std::thread([receiver, target] {
            const HANDLE in = ::GetStdHandle(STD_INPUT_HANDLE);
            char buf[256];
            for (;;) {
                DWORD n = 0;
                const bool ok = in != INVALID_HANDLE_VALUE && ::ReadFile(in, buf, DWORD(sizeof buf), &n, nullptr);
                const QByteArray bytes(buf, ok ? int(n) : 0);
                const bool end = !ok || n == 0;
                QMetaObject::invokeMethod(
                    receiver,
                    [receiver, target, bytes, end] {
                        if (!receiver)
                            return;
                        if (end)
                            target->ended();
                        else
                            target->arrived(bytes);
                    },
                    Qt::QueuedConnection);
                if (end)
                    return;
            }
        }).detach();
    }
    ~Reader() { delete m_receiver; }

private:
    QObject *m_receiver = nullptr; // lives in the owner's thread; gone, the thread's chunks are dropped
};

OperatorInput::OperatorInput() : m_reader(std::make_unique<Reader>(*this)) {}

OperatorInput::~OperatorInput() = default;

} // namespace imudesk::cli
