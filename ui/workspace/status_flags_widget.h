#pragma once
// A row of small labels, one per MAIN_STATUS flag: coloured by meaning when set, grey
// when clear, dimmed when the latest frame carries no status word. Tooltips quote
// the flag's meaning from MainStatus::definitions(), translated.
#include <QWidget>

#include <optional>
#include <vector>

class QLabel;

namespace imudesk::ui {

class StatusFlagsWidget : public QWidget {
    Q_OBJECT
public:
    explicit StatusFlagsWidget(QWidget *parent = nullptr);

    // nullopt: the frame has no MAIN_STATUS (older firmware or another frame type).
    void setStatus(std::optional<quint16> raw);
    std::optional<quint16> status() const { return m_status; }
    // Text of the label for `bit` ("" when no flag has that bit).
    QString flagText(int bit) const;
    QString flagToolTip(int bit) const;

protected:
    void changeEvent(QEvent *event) override;

private:
    void updateLabels(bool force);
    void retranslateUi();

    struct Flag {
        int bit = 0;
        QLabel *label = nullptr;
        int shown = -1; // -1 never painted, 0 clear, 1 set, 2 unknown
    };
    QLabel *m_title = nullptr;
    std::vector<Flag> m_flags;
    std::optional<quint16> m_status;
};

} // namespace imudesk::ui
