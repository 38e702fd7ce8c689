#include "operator_input.h"

#include "cli_context.h"

#include <cstdio>

namespace imudesk::cli {

std::optional<QString> OperatorInput::line()
{
    waitFor([&] { return m_buffer.contains('\n') || m_eof || interrupted(); }, -1);
    const int nl = int(m_buffer.indexOf('\n'));
    if (nl < 0 || interrupted())
        return std::nullopt;
    const QString l = QString::fromLocal8Bit(m_buffer.left(nl)).trimmed();
    m_buffer.remove(0, nl + 1);
    return l;
}

bool OperatorInput::confirm(const QString &question)
{
    std::fprintf(stderr, "%s [y/N] ", qPrintable(question));
    std::fflush(stderr);
    const auto answer = line();
    return answer && (answer->compare(QLatin1String("y"), Qt::CaseInsensitive) == 0
                      || answer->compare(QLatin1String("yes"), Qt::CaseInsensitive) == 0);
}

void OperatorInput::ended()
{
    m_eof = true;
    if (!m_buffer.isEmpty() && !m_buffer.endsWith('\n'))
        m_buffer += '\n'; // a last line without its end still counts
}

} // namespace imudesk::cli
