#include "ui/station/station_tiles.h"

#include <QDir>
#include <QEvent>
#include <QFontMetrics>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QProgressBar>
#include <QTextLayout>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace imudesk::ui {

using station::ModuleResult;
using station::Verdict;

namespace {

// A verdict's colour (the verdict word is always written beside it): pass green, fail red,
// running blue, waiting grey.
QString verdictColour(Verdict v)
{
    switch (v) {
    case Verdict::Pass: return QStringLiteral("#2e7d32");
    case Verdict::Fail: return QStringLiteral("#c62828");
    case Verdict::Running: return QStringLiteral("#1565c0");
    case Verdict::Pending:
    case Verdict::Skipped: break;
    }
    return QStringLiteral("#757575");
}

} // namespace

StationTile::StationTile(int index, QWidget *parent) : QFrame(parent)
{
    setObjectName(QStringLiteral("stationTile_%1").arg(index));
    setFocusPolicy(Qt::StrongFocus);
    setCursor(Qt::PointingHandCursor);
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    m_port = new ElidedLabel(1, this);
    m_port->setObjectName(QStringLiteral("port"));
    QFont bold = m_port->font();
    bold.setBold(true);
    m_port->setFont(bold);
    m_verdict = new QLabel(this);
    m_verdict->setObjectName(QStringLiteral("verdict"));
    m_verdict->setAlignment(Qt::AlignCenter);
    m_identity = new ElidedLabel(2, this); // a firmware update adds "1.6.6 → 1.7.1"
    m_identity->setObjectName(QStringLiteral("identity"));
    m_step = new ElidedLabel(1, this);
    m_step->setObjectName(QStringLiteral("step"));
    m_progress = new QProgressBar(this);
    m_progress->setObjectName(QStringLiteral("progress"));
    m_progress->setRange(0, 1000);
    m_progress->setTextVisible(true);
    m_failure = new ElidedLabel(4, this); // the failing values, as many as fit
    m_failure->setObjectName(QStringLiteral("failure"));
    m_failure->setStyleSheet(QStringLiteral("color: #c62828;"));

    // The report of a module whose test has ended; no taller than the verdict beside it, so
    // the tile keeps its height (a tray of eight fits a laptop's window).
    m_report = new QToolButton(this);
    m_report->setObjectName(QStringLiteral("openReport"));
    m_report->setAutoRaise(true);
    m_report->setFocusPolicy(Qt::TabFocus);
    m_report->setCursor(Qt::PointingHandCursor);
    m_report->setStyleSheet(QStringLiteral("QToolButton { padding: 0px 4px; }"));
    m_report->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Ignored);
    m_report->hide();
    connect(m_report, &QToolButton::clicked, this, [this] {
        if (reportRequested)
            reportRequested();
    });

    auto *top = new QHBoxLayout;
    top->setContentsMargins(0, 0, 0, 0);
    top->addWidget(m_port, 1);
    top->addWidget(m_report);
    top->addWidget(m_verdict);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(10, 6, 8, 6);
    layout->setSpacing(3);
    layout->addLayout(top);
    layout->addWidget(m_identity);
    layout->addWidget(m_step);
    layout->addWidget(m_progress);
    layout->addWidget(m_failure);
    setVerdict(Verdict::Pending, QString());
}

void StationTile::showModule(const ModuleResult &r, const QString &step, const QString &verdict, const QString &failure,
                             const QString &toolTip)
{
    m_port->setFullText(r.port);
    QString firmware = r.firmware;
    if (!r.firmwareAfter.isEmpty())
        firmware = tr("%1 → %2").arg(r.firmware, r.firmwareAfter);
    if (r.serial.isEmpty() && r.product.isEmpty())
        m_identity->setFullText(tr("not identified yet"));
    else
        m_identity->setFullText(tr("SN %1 · %2 · %3")
                                    .arg(r.serial.isEmpty() ? tr("(none)") : r.serial,
                                         r.product.isEmpty() ? tr("(no product)") : r.product,
                                         firmware.isEmpty() ? tr("(no firmware)") : firmware));
    m_step->setFullText(step);
    const int permille = int(std::lround(std::clamp(r.progress, 0.0, 1.0) * 1000));
    m_progress->setValue(permille);
    m_progress->setFormat(tr("%1 %").arg(permille / 10));
    m_progress->setToolTip(tr("%1 % of the plan, each step weighted by how long it takes").arg(permille / 10));
    m_failure->setFullText(failure);
    m_report->setText(tr("Report"));
    m_report->setToolTip(tr("Open this module's PDF report: %1").arg(QDir::toNativeSeparators(r.reportPath)));
    m_report->setAccessibleName(tr("Report of %1").arg(r.port));
    m_report->setVisible(!r.reportPath.isEmpty() && r.verdict != Verdict::Running && r.verdict != Verdict::Pending);
    setVerdict(r.verdict, verdict);
    setToolTip(toolTip);
    setAccessibleName(tr("%1: %2").arg(r.port, verdict));
    setAccessibleDescription(failure.isEmpty() ? step : failure);
}

void StationTile::mouseReleaseEvent(QMouseEvent *event)
{
    if (event->button() == Qt::LeftButton && rect().contains(event->position().toPoint()) && activated)
        activated();
    QFrame::mouseReleaseEvent(event);
}

void StationTile::keyPressEvent(QKeyEvent *event)
{
    if ((event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter || event->key() == Qt::Key_Space)
        && activated) {
        activated();
        return;
    }
    QFrame::keyPressEvent(event);
}

void StationTile::setVerdict(Verdict v, const QString &text)
{
    if (v == m_shownVerdict && text == m_verdict->text())
        return;
    m_shownVerdict = v;
    m_verdict->setText(text);
    const QString colour = verdictColour(v);
    m_verdict->setStyleSheet(QStringLiteral("QLabel { background: %1; color: white; border-radius: 3px; "
                                            "padding: 1px 8px; font-weight: bold; }")
                                 .arg(colour));
    // The frame in the verdict's colour, thick on the left; a focused tile gets a dark outline.
    setStyleSheet(QStringLiteral("QFrame#%1 { border: 1px solid %2; border-left: 6px solid %2; }"
                                 "QFrame#%1:focus { border: 2px solid palette(highlight); border-left: 6px solid %2; }")
                      .arg(objectName(), colour));
}

TileGridLayout::TileGridLayout(QWidget *parent) : QLayout(parent)
{
    setContentsMargins(0, 0, 0, 0);
}

TileGridLayout::~TileGridLayout()
{
    while (QLayoutItem *item = takeAt(0))
        delete item;
}

QLayoutItem *TileGridLayout::takeAt(int index)
{
    return index >= 0 && index < m_items.size() ? m_items.takeAt(index) : nullptr;
}

int TileGridLayout::columnsFor(int width) const
{
    const int fit = (width + kTileSpacing) / (kMinTileWidth + kTileSpacing);
    return std::clamp(fit, 1, std::max(1, count()));
}

int TileGridLayout::heightForWidth(int width) const
{
    if (m_items.isEmpty())
        return 0;
    const int rows = (count() + columnsFor(width) - 1) / columnsFor(width);
    return rows * tileHeight() + (rows - 1) * kTileSpacing;
}

QSize TileGridLayout::sizeHint() const
{
    const int columns = std::min(std::max(1, count()), 4);
    const int width = columns * kMinTileWidth + (columns - 1) * kTileSpacing;
    return {width, heightForWidth(width)};
}

QSize TileGridLayout::minimumSize() const
{
    int width = 0;
    for (const QLayoutItem *item : m_items)
        width = std::max(width, item->minimumSize().width());
    return {width, m_items.isEmpty() ? 0 : tileHeight()};
}

void TileGridLayout::setGeometry(const QRect &rect)
{
    QLayout::setGeometry(rect);
    if (m_items.isEmpty())
        return;
    const int columns = columnsFor(rect.width());
    const int width = (rect.width() - (columns - 1) * kTileSpacing) / columns;
    const int height = tileHeight();
    for (int i = 0; i < count(); ++i) {
        const int row = i / columns, column = i % columns;
        m_items[i]->setGeometry(QRect(rect.x() + column * (width + kTileSpacing),
                                      rect.y() + row * (height + kTileSpacing), width, height));
    }
    m_columns = columns;
}

int TileGridLayout::tileHeight() const
{
    int height = 0;
    for (const QLayoutItem *item : m_items)
        height = std::max(height, item->sizeHint().height());
    return height;
}

} // namespace imudesk::ui
