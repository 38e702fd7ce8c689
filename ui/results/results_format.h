#pragma once
// How the results window words what the results database holds: outcomes in words and colour,
// times in local time, values and limits, and texts of any length (a serial number or a plan
// name as the station stored it, which may be 10 kB) cut for a cell or a combo box, with the
// whole text in a tooltip that wraps. Texts are shown as they are: never read as HTML.
#include "core/results/result_record.h"

#include <QColor>
#include <QCoreApplication>
#include <QDateTime>
#include <QString>

#include <optional>

QT_BEGIN_NAMESPACE
class QComboBox;
QT_END_NAMESPACE

namespace imudesk::ui {

class ResultsFormat {
    Q_DECLARE_TR_FUNCTIONS(imudesk::ui::ResultsFormat)

public:
    // A cell or a combo box's item shows at most this many characters of a text (the view
    // elides it further to its width); the tooltip has it all.
    static constexpr int kMaxShownChars = 80;

    // "PASS", "PASS (marginal)", "FAIL", "ERROR", "ABORTED"
    static QString outcome(results::Outcome o, bool marginal = false);
    static QColor outcomeColour(results::Outcome o, bool marginal = false);
    // Local time, to the second; empty for an invalid time.
    static QString time(const QDateTime &t);
    // Six significant digits.
    static QString number(double v);
    // "0.1 … 0.5", "≤ 0.5", "≥ 0.1"; empty without either.
    static QString range(const std::optional<double> &low, const std::optional<double> &high);
    // One line (line breaks as spaces), at most kMaxShownChars characters, "…" where cut.
    static QString shortText(const QString &text);
    // The whole text as a tooltip that wraps (a plain text tooltip is one line however long).
    static QString toolTip(const QString &text);
    // A combo box item: shortText shown, the whole text as its data and tooltip.
    static void addComboItem(QComboBox *combo, const QString &shown, const QString &value);
};

} // namespace imudesk::ui
