#include "operator_input.h"

#include <QSocketNotifier>

#include <unistd.h>

namespace imudesk::cli {

// Descriptor 0 watched by the event loop; a read per notification.
class OperatorInput::Reader {
public:
    explicit Reader(OperatorInput &owner) : m_notifier(STDIN_FILENO, QSocketNotifier::Read)
    {
        QObject::connect(&m_notifier, &QSocketNotifier::activated, &m_notifier, [this, &owner] {
            char buf[256];
            const ssize_t n = ::read(STDIN_FILENO, buf, sizeof buf);
            if (n <= 0) {
                m_notifier.setEnabled(false);
                owner.ended();
                return;
            }
            owner.arrived(QByteArray(buf, int(n)));
        });
    }

private:
    QSocketNotifier m_notifier;
};

OperatorInput::OperatorInput() : m_reader(std::make_unique<Reader>(*this)) {}

OperatorInput::~OperatorInput() = default;

} // namespace imudesk::cli
