#pragma once
// Lines from standard input (a terminal or a pipe) as they arrive, read inside the event loop
// so the session keeps running while the operator takes their time. What waits for standard
// input is one platform file each: operator_input_posix.cpp (a socket notifier on descriptor 0)
// and operator_input_windows.cpp (a thread that reads the console or pipe).
#include <QByteArray>
#include <QString>

#include <memory>
#include <optional>

namespace imudesk::cli {

class OperatorInput {
public:
    OperatorInput();
    ~OperatorInput();
    OperatorInput(const OperatorInput &) = delete;
    OperatorInput &operator=(const OperatorInput &) = delete;

    // The next line without its end; nullopt at the end of the input or on Ctrl+C.
    std::optional<QString> line();
    // A yes/no question on stderr; anything but y/yes (or the end of the input) is no.
    bool confirm(const QString &question);

private:
    // The platform's part: calls arrived(bytes) and, once, ended() in the owner's thread.
    class Reader;
    void arrived(const QByteArray &bytes) { m_buffer.append(bytes); }
    void ended();

    std::unique_ptr<Reader> m_reader;
    QByteArray m_buffer;
    bool m_eof = false;
};

} // namespace imudesk::cli
