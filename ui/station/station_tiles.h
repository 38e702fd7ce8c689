#pragma once
// The pieces of the station window's tile grid: a label that elides over a fixed number of
// lines, one tile per module, and the layout that puts the tiles in as many columns as fit.
#include "core/station/station_result.h"
#include "ui/common/elided_label.h"

#include <QCoreApplication>
#include <QFrame>
#include <QLabel>
#include <QLayout>
#include <QList>

#include <functional>

QT_BEGIN_NAMESPACE
class QProgressBar;
class QToolButton;
QT_END_NAMESPACE

namespace imudesk::ui {

// One module of the tray: port and verdict (word and colour), serial number and product, the
// step under way, progress, and for a failure the failing step with its values. A click,
// Enter or Space asks for the module's workspace; once the module's PDF report is written, a
// Report button beside the verdict (reached with Tab) asks for it.
class StationTile : public QFrame {
    Q_DECLARE_TR_FUNCTIONS(imudesk::ui::StationTile)

public:
    std::function<void()> activated;
    std::function<void()> reportRequested;

    StationTile(int index, QWidget *parent);
    void showModule(const station::ModuleResult &r, const QString &step, const QString &verdict,
                    const QString &failure, const QString &toolTip);

protected:
    void mouseReleaseEvent(QMouseEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;

private:
    void setVerdict(station::Verdict v, const QString &text);

    ElidedLabel *m_port, *m_identity, *m_step, *m_failure;
    QLabel *m_verdict;
    QToolButton *m_report;
    QProgressBar *m_progress;
    station::Verdict m_shownVerdict = station::Verdict::Skipped; // not shown yet
};

// The tiles in as many columns as fit at kMinTileWidth (at most one per tile), every row as
// high as a tile wants: the grid's height follows its width, so the scroll area around it
// shows a scroll bar only when the tray does not fit the window.
class TileGridLayout : public QLayout {
public:
    static constexpr int kMinTileWidth = 290; // the grid's columns: 4 in a 1366-px window, 6 in a 1920-px one
    static constexpr int kTileSpacing = 8;

    explicit TileGridLayout(QWidget *parent);
    ~TileGridLayout() override;

    void addItem(QLayoutItem *item) override { m_items.append(item); }
    int count() const override { return int(m_items.size()); }
    QLayoutItem *itemAt(int index) const override { return m_items.value(index); }
    QLayoutItem *takeAt(int index) override;
    Qt::Orientations expandingDirections() const override { return Qt::Horizontal; }
    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int width) const override;
    QSize sizeHint() const override;
    QSize minimumSize() const override;
    void setGeometry(const QRect &rect) override;

    int columnsFor(int width) const;
    int columns() const { return m_columns; }

private:
    int tileHeight() const;

    QList<QLayoutItem *> m_items;
    int m_columns = 1;
};

} // namespace imudesk::ui
