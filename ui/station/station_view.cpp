#include "station/station_view.h"

#include "reports/station_report.h"
#include "sim/pty_simulator.h"
#include "station/plan_editor_dialog.h"
#include "station/run_folder.h"
#include "station/station_model.h"
#include "station/station_runner.h"
#include "workspace/window_helpers.h"

#include <QCheckBox>
#include <QCloseEvent>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QImageWriter>
#include <QKeyEvent>
#include <QLabel>
#include <QLayout>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QMouseEvent>
#include <QProgressBar>
#include <QPushButton>
#include <QScreen>
#include <QScrollArea>
#include <QSerialPortInfo>
#include <QSettings>
#include <QShortcut>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTextLayout>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace imudesk::ui {

using station::ModuleResult;
using station::StationRunner;
using station::TestPlan;
using station::Verdict;

namespace {

constexpr int kMinTileWidth = 290; // the grid's columns: 4 in a 1366-px window, 6 in a 1920-px one
constexpr int kTileSpacing = 8;

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

// A label that shows as much of its text as fits in up to maxLines lines, the last one
// elided, and the whole text in its tooltip when anything was left out; it never asks for
// more width than it gets, so a long serial number or failure cannot widen the grid.
class ElidedLabel : public QLabel {
public:
    ElidedLabel(int maxLines, QWidget *parent) : QLabel(parent), m_maxLines(std::max(1, maxLines))
    {
        setTextFormat(Qt::PlainText);
        setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    }

    void setFullText(const QString &text)
    {
        if (text == m_full)
            return;
        m_full = text;
        updateGeometry();
        relayout();
    }
    const QString &fullText() const { return m_full; }
    // Shown in the tooltip after the full text (or alone when nothing is elided).
    void setExtraToolTip(const QString &extra)
    {
        m_extra = extra;
        relayout();
    }

    QSize minimumSizeHint() const override
    {
        const QFontMetrics fm(font());
        const QMargins m = contentsMargins();
        // As QLabel sets lines: one font height, and a line spacing more for each further line.
        return {fm.horizontalAdvance(QStringLiteral("M…")) + m.left() + m.right(),
                fm.height() + (m_maxLines - 1) * fm.lineSpacing() + m.top() + m.bottom()};
    }
    QSize sizeHint() const override
    {
        const QFontMetrics fm(font());
        const QMargins m = contentsMargins();
        QSize s = minimumSizeHint();
        s.setWidth(std::max(s.width(), fm.horizontalAdvance(m_full) + m.left() + m.right()));
        return s;
    }

protected:
    void resizeEvent(QResizeEvent *event) override
    {
        QLabel::resizeEvent(event);
        relayout();
    }
    void changeEvent(QEvent *event) override
    {
        QLabel::changeEvent(event);
        if (event->type() == QEvent::FontChange || event->type() == QEvent::StyleChange)
            relayout();
    }

private:
    void relayout()
    {
        const int width = contentsRect().width();
        QString full = m_full;
        full.replace(QLatin1Char('\n'), QLatin1Char(' '));
        const QFontMetrics fm(font());
        QStringList lines;
        if (width <= 0) {
            lines << QString();
        } else if (fm.horizontalAdvance(full) <= width) {
            lines << full;
        } else {
            // Break into lines as a word-wrapped label would; the last line allowed takes the
            // rest, elided.
            QTextLayout layout(full, font());
            QTextOption option;
            option.setWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
            layout.setTextOption(option);
            layout.beginLayout();
            for (;;) {
                QTextLine line = layout.createLine();
                if (!line.isValid())
                    break;
                line.setLineWidth(width);
                if (int(lines.size()) + 1 == m_maxLines) {
                    lines << fm.elidedText(full.mid(line.textStart()).trimmed(), Qt::ElideRight, width);
                    break;
                }
                const QString text = full.mid(line.textStart(), line.textLength()).trimmed();
                lines << (fm.horizontalAdvance(text) <= width ? text : fm.elidedText(text, Qt::ElideRight, width));
            }
            layout.endLayout();
        }
        const QString shown = lines.join(QLatin1Char('\n'));
        QLabel::setText(shown);
        const bool elided = QString(shown).replace(QLatin1Char('\n'), QLatin1Char(' ')).simplified() != full.simplified();
        QStringList tip;
        if (elided)
            tip << m_full;
        if (!m_extra.isEmpty())
            tip << m_extra;
        setToolTip(tip.join(QStringLiteral("\n\n")));
    }

    int m_maxLines;
    QString m_full, m_extra;
};

// One module of the tray: port and verdict (word and colour), serial number and product, the
// step under way, progress, and for a failure the failing step with its values. A click,
// Enter or Space asks for the module's workspace.
class StationTile : public QFrame {
    Q_DECLARE_TR_FUNCTIONS(imudesk::ui::StationTile)

public:
    std::function<void()> activated;

    StationTile(int index, QWidget *parent) : QFrame(parent)
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

        auto *top = new QHBoxLayout;
        top->setContentsMargins(0, 0, 0, 0);
        top->addWidget(m_port, 1);
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

    void showModule(const ModuleResult &r, const QString &step, const QString &verdict, const QString &failure,
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
        setVerdict(r.verdict, verdict);
        setToolTip(toolTip);
        setAccessibleName(tr("%1: %2").arg(r.port, verdict));
        setAccessibleDescription(failure.isEmpty() ? step : failure);
    }

protected:
    void mouseReleaseEvent(QMouseEvent *event) override
    {
        if (event->button() == Qt::LeftButton && rect().contains(event->position().toPoint()) && activated)
            activated();
        QFrame::mouseReleaseEvent(event);
    }
    void keyPressEvent(QKeyEvent *event) override
    {
        if ((event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter || event->key() == Qt::Key_Space)
            && activated) {
            activated();
            return;
        }
        QFrame::keyPressEvent(event);
    }

private:
    void setVerdict(Verdict v, const QString &text)
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

    ElidedLabel *m_port, *m_identity, *m_step, *m_failure;
    QLabel *m_verdict;
    QProgressBar *m_progress;
    Verdict m_shownVerdict = Verdict::Skipped; // not shown yet
};

// The tiles in as many columns as fit at kMinTileWidth (at most one per tile), every row as
// high as a tile wants: the grid's height follows its width, so the scroll area around it
// shows a scroll bar only when the tray does not fit the window.
class TileGridLayout : public QLayout {
public:
    explicit TileGridLayout(QWidget *parent) : QLayout(parent) { setContentsMargins(0, 0, 0, 0); }
    ~TileGridLayout() override
    {
        while (QLayoutItem *item = takeAt(0))
            delete item;
    }

    void addItem(QLayoutItem *item) override { m_items.append(item); }
    int count() const override { return int(m_items.size()); }
    QLayoutItem *itemAt(int index) const override { return m_items.value(index); }
    QLayoutItem *takeAt(int index) override
    {
        return index >= 0 && index < m_items.size() ? m_items.takeAt(index) : nullptr;
    }
    Qt::Orientations expandingDirections() const override { return Qt::Horizontal; }
    bool hasHeightForWidth() const override { return true; }

    int columnsFor(int width) const
    {
        const int fit = (width + kTileSpacing) / (kMinTileWidth + kTileSpacing);
        return std::clamp(fit, 1, std::max(1, count()));
    }
    int heightForWidth(int width) const override
    {
        if (m_items.isEmpty())
            return 0;
        const int rows = (count() + columnsFor(width) - 1) / columnsFor(width);
        return rows * tileHeight() + (rows - 1) * kTileSpacing;
    }
    QSize sizeHint() const override
    {
        const int columns = std::min(std::max(1, count()), 4);
        const int width = columns * kMinTileWidth + (columns - 1) * kTileSpacing;
        return {width, heightForWidth(width)};
    }
    QSize minimumSize() const override
    {
        int width = 0;
        for (const QLayoutItem *item : m_items)
            width = std::max(width, item->minimumSize().width());
        return {width, m_items.isEmpty() ? 0 : tileHeight()};
    }
    void setGeometry(const QRect &rect) override
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
    int columns() const { return m_columns; }

private:
    int tileHeight() const
    {
        int height = 0;
        for (const QLayoutItem *item : m_items)
            height = std::max(height, item->sizeHint().height());
        return height;
    }

    QList<QLayoutItem *> m_items;
    int m_columns = 1;
};

// ---------------------------------------------------------------- settings

void StationSettings::load(QSettings &settings)
{
    reportFolder = settings.value(QLatin1String(kReportFolderKey)).toString();
    planPath = settings.value(QLatin1String(kPlanKey)).toString();
}

void StationSettings::save(QSettings &settings) const
{
    settings.setValue(QLatin1String(kReportFolderKey), reportFolder);
    settings.setValue(QLatin1String(kPlanKey), planPath);
}

QString StationSettings::defaultReportFolder()
{
    return QDir(QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation))
        .filePath(QStringLiteral("ImuDesk/station"));
}

// ---------------------------------------------------------------- the window

StationView::StationView(QWidget *parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("stationView"));
    // A window of its own, also when the main window owns it.
    setWindowFlag(Qt::Window);
    m_model = new StationModel(this);

    // Plan: its name and steps, Open…, Edit…, New from example.
    m_planTitle = new QLabel(this);
    m_planName = new ElidedLabel(1, this);
    m_planName->setObjectName(QStringLiteral("planName"));
    m_openPlan = new QPushButton(this);
    m_openPlan->setObjectName(QStringLiteral("openPlan"));
    connect(m_openPlan, &QPushButton::clicked, this, &StationView::choosePlan);
    m_editPlan = new QPushButton(this);
    m_editPlan->setObjectName(QStringLiteral("editPlan"));
    connect(m_editPlan, &QPushButton::clicked, this, [this] { editPlan(); });
    m_examplePlan = new QPushButton(this);
    m_examplePlan->setObjectName(QStringLiteral("examplePlan"));
    connect(m_examplePlan, &QPushButton::clicked, this, &StationView::newFromExample);
    auto *planRow = new QHBoxLayout;
    planRow->addWidget(m_planName, 1);
    planRow->addWidget(m_openPlan);
    planRow->addWidget(m_editPlan);
    planRow->addWidget(m_examplePlan);

    // Ports: a check box per port, flowing in rows; Refresh and the simulated tray beside.
    m_portsTitle = new QLabel(this);
    m_ports = new QListWidget(this);
    m_ports->setObjectName(QStringLiteral("stationPorts"));
    m_ports->setFlow(QListView::LeftToRight);
    m_ports->setWrapping(true);
    m_ports->setResizeMode(QListView::Adjust);
    m_ports->setSpacing(2);
    m_ports->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_portsTitle->setBuddy(m_ports);
    connect(m_ports, &QListWidget::itemChanged, this, [this] { updateActions(); });
    m_refreshPorts = new QPushButton(this);
    m_refreshPorts->setObjectName(QStringLiteral("refreshPorts"));
    connect(m_refreshPorts, &QPushButton::clicked, this, &StationView::refreshPorts);
    m_tray = new QPushButton(this);
    m_tray->setObjectName(QStringLiteral("simulatedTray"));
    connect(m_tray, &QPushButton::clicked, this, &StationView::openTrayDialog);
    auto *portButtons = new QVBoxLayout;
    portButtons->setContentsMargins(0, 0, 0, 0);
    portButtons->addWidget(m_refreshPorts);
    portButtons->addWidget(m_tray);
    portButtons->addStretch(1);
    auto *portRow = new QHBoxLayout;
    portRow->addWidget(m_ports, 1);
    portRow->addLayout(portButtons);
    // Two rows of ports, as high as the two buttons beside them.
    m_ports->setFixedHeight(std::max(m_refreshPorts->sizeHint().height() * 2 + 6,
                                     2 * (fontMetrics().height() + 8) + 2 * m_ports->frameWidth()));

    // Report folder.
    m_folderTitle = new QLabel(this);
    m_folder = new QLineEdit(this);
    m_folder->setObjectName(QStringLiteral("reportFolder"));
    m_folderTitle->setBuddy(m_folder);
    connect(m_folder, &QLineEdit::editingFinished, this, [this] { setReportFolder(reportFolder()); });
    m_chooseFolder = new QPushButton(this);
    m_chooseFolder->setObjectName(QStringLiteral("chooseReportFolder"));
    connect(m_chooseFolder, &QPushButton::clicked, this, &StationView::chooseReportFolder);
    auto *folderRow = new QHBoxLayout;
    folderRow->addWidget(m_folder, 1);
    folderRow->addWidget(m_chooseFolder);

    // Start, Cancel, Re-run failed; their keys are shortcuts of this window (Ctrl+R here is
    // not the main window's Record).
    m_start = new QPushButton(this);
    m_start->setObjectName(QStringLiteral("startStation"));
    connect(m_start, &QPushButton::clicked, this, [this] { start(); });
    m_cancel = new QPushButton(this);
    m_cancel->setObjectName(QStringLiteral("cancelStation"));
    connect(m_cancel, &QPushButton::clicked, this, &StationView::cancel);
    m_rerun = new QPushButton(this);
    m_rerun->setObjectName(QStringLiteral("rerunFailed"));
    connect(m_rerun, &QPushButton::clicked, this, &StationView::rerunFailed);
    const auto shortcut = [this](const QKeySequence &keys, QPushButton *button) {
        auto *s = new QShortcut(keys, this);
        connect(s, &QShortcut::activated, button, [button] {
            if (button->isEnabled())
                button->click();
        });
    };
    shortcut(QKeySequence(Qt::CTRL | Qt::Key_R), m_start);
    shortcut(QKeySequence(Qt::Key_Escape), m_cancel);
    shortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R), m_rerun);
    auto *runRow = new QHBoxLayout;
    runRow->addWidget(m_start);
    runRow->addWidget(m_cancel);
    runRow->addWidget(m_rerun);
    runRow->addStretch(1);

    auto *top = new QGridLayout;
    top->addWidget(m_planTitle, 0, 0);
    top->addLayout(planRow, 0, 1);
    top->addWidget(m_portsTitle, 1, 0, Qt::AlignTop);
    top->addLayout(portRow, 1, 1);
    top->addWidget(m_folderTitle, 2, 0);
    top->addLayout(folderRow, 2, 1);
    top->addLayout(runRow, 3, 1);
    top->setColumnStretch(1, 1);

    // The summary line, larger, then the tiles.
    m_summary = new ElidedLabel(1, this);
    m_summary->setObjectName(QStringLiteral("stationSummary"));
    QFont summaryFont = m_summary->font();
    summaryFont.setBold(true);
    summaryFont.setPointSizeF(summaryFont.pointSizeF() * 1.15);
    m_summary->setFont(summaryFont);
    m_placeholder = new QLabel(this);
    m_placeholder->setObjectName(QStringLiteral("stationPlaceholder"));
    m_placeholder->setWordWrap(true);
    m_placeholder->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    m_tileArea = new QWidget;
    m_tileArea->setObjectName(QStringLiteral("stationTiles"));
    m_grid = new TileGridLayout(m_tileArea);
    m_scroll = new QScrollArea(this);
    m_scroll->setObjectName(QStringLiteral("stationTileScroll"));
    m_scroll->setFrameShape(QFrame::NoFrame);
    m_scroll->setWidgetResizable(true);
    m_scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_scroll->setWidget(m_tileArea);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(m_summary);
    layout->addWidget(m_placeholder);
    layout->addWidget(m_scroll, 1);

    connect(m_model, &QAbstractItemModel::dataChanged, this,
            [this](const QModelIndex &first, const QModelIndex &last) { updateTiles(first.row(), last.row()); });
    connect(m_model, &QAbstractItemModel::modelReset, this, &StationView::rebuildTiles);
    connect(m_model, &StationModel::refreshed, this, [this] {
        updateSummary();
        updateActions();
    });

    {
        QSettings store;
        m_settings.load(store);
    }
    m_folder->setText(QDir::toNativeSeparators(
        m_settings.reportFolder.isEmpty() ? StationSettings::defaultReportFolder() : m_settings.reportFolder));
    retranslateUi();
    refreshPorts();
    rebuildTiles();
    // The plan used last, when it is still there.
    if (!m_settings.planPath.isEmpty() && QFileInfo::exists(m_settings.planPath))
        openPlan(m_settings.planPath);
    updatePlanLabel();
    updateActions();

    // At most the screen's work area, at most 1600x900.
    const QSize room = screen() ? screen()->availableGeometry().size() : QSize(1366, 768);
    resize(QSize(1600, 900).boundedTo(room * 95 / 100));
}

StationView::~StationView()
{
    // The runner's sessions close before the simulated modules they talk to go away.
    m_model->setRunner(nullptr);
    m_runner.reset();
    stopSimulatedTray();
}

void StationView::retranslateUi()
{
    setWindowTitle(tr("Production station"));
    m_planTitle->setText(tr("Plan:"));
    m_openPlan->setText(tr("Open…"));
    m_openPlan->setToolTip(tr("Open a test plan (a .json file saved by the plan editor)"));
    m_editPlan->setText(tr("Edit…"));
    m_editPlan->setToolTip(tr("Edit the plan's steps and limits; the next Start uses the saved plan"));
    m_examplePlan->setText(tr("New from example"));
    m_examplePlan->setToolTip(tr("A new plan from the example for HI14 modules, every step with its default "
                                 "limits, opened in the editor (without a firmware image; the profile step is off)"));
    m_portsTitle->setText(tr("Ports:"));
    m_ports->setToolTip(tr("The modules to test: check the port of each"));
    m_refreshPorts->setText(tr("Refresh"));
    m_refreshPorts->setToolTip(tr("Look for serial ports again (after plugging in an adapter)"));
    m_tray->setText(tr("Simulated tray…"));
    m_tray->setToolTip(tr("Start simulated HI14 modules on pseudo-terminals, some of them with faults, to try "
                          "the station without hardware"));
    m_folderTitle->setText(tr("Reports:"));
    m_folder->setToolTip(tr("Each run gets a folder here: the plan, summary.csv and summary.jsonl, a PDF "
                            "report per module and the evidence recordings"));
    m_chooseFolder->setText(tr("Choose…"));
    m_chooseFolder->setToolTip(tr("Choose the folder for the run folders"));
    m_start->setText(tr("Start"));
    m_start->setToolTip(tr("Run the plan on every checked port at once (Ctrl+R)"));
    m_cancel->setText(tr("Cancel"));
    m_cancel->setToolTip(tr("Stop every module's test; the running steps fail as cancelled (Esc)"));
    m_rerun->setText(tr("Re-run failed"));
    m_rerun->setToolTip(tr("Test the modules that failed again, into the same run folder as their next "
                           "attempt (Ctrl+Shift+R)"));
    m_placeholder->setText(tr("Choose a plan and check the ports of the modules, then press Start (Ctrl+R). "
                              "Each module gets a tile here; click a tile to open that module's workspace."));
    // Port items and tiles carry translated texts too.
    for (int i = 0; i < m_ports->count(); ++i) {
        QListWidgetItem *item = m_ports->item(i);
        const QString port = item->data(Qt::UserRole).toString();
        if (m_simPorts.contains(port)) {
            item->setText(tr("%1 (simulated)").arg(port));
            item->setToolTip(m_simNotes.value(port));
        }
    }
    updatePlanLabel();
    m_model->refresh(true);
    updateSummary();
}

void StationView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange && m_start)
        retranslateUi();
    QWidget::changeEvent(event);
}

void StationView::closeEvent(QCloseEvent *event)
{
    // An editor with unsaved changes asks first; answering Cancel keeps both windows open.
    if (m_editor && m_editor->isVisible() && !m_editor->close()) {
        event->ignore();
        return;
    }
    // A run still going is cancelled (each module's report says so), then the simulated
    // modules stop: nothing of the station outlives its window.
    if (running())
        m_runner->cancel();
    stopSimulatedTray();
    QWidget::closeEvent(event);
}

void StationView::showError(const QString &message)
{
    if (m_errorPresenter) {
        m_errorPresenter(message);
        return;
    }
    WindowHelpers::showError(this, m_errorBox, tr("Production station"), message);
}

bool StationView::saveScreenshot(const QString &path, QString *error)
{
    return WindowHelpers::saveScreenshot(this, path, error);
}

void StationView::rememberSettings()
{
    if (!m_remember)
        return;
    QSettings store;
    m_settings.save(store);
}

// ---------------------------------------------------------------- plan

TestPlan StationView::demoPlan()
{
    TestPlan plan = TestPlan::example();
    for (station::PlanStep &s : plan.steps) {
        if (s.kind == station::StepKind::Firmware)
            s.params[QStringLiteral("image")] = QString();
        if (s.kind == station::StepKind::Profile)
            s.enabled = false;
    }
    return plan;
}

bool StationView::openPlan(const QString &path)
{
    QString error;
    const auto plan = TestPlan::load(path, &error);
    if (!plan) {
        showError(tr("The plan %1 could not be opened: %2").arg(QDir::toNativeSeparators(path), error));
        return false;
    }
    setPlan(*plan, QFileInfo(path).absoluteFilePath());
    return true;
}

void StationView::setPlan(const TestPlan &plan, const QString &path)
{
    m_plan = plan;
    m_planPath = path;
    m_havePlan = true;
    if (!path.isEmpty() && path != m_settings.planPath) {
        m_settings.planPath = path;
        rememberSettings();
    }
    updatePlanLabel();
    updateActions();
}

void StationView::updatePlanLabel()
{
    if (!m_havePlan) {
        m_planName->setFullText(tr("No plan yet: open one, or start from the example"));
        m_planName->setExtraToolTip(QString());
        return;
    }
    int enabled = 0;
    QStringList steps;
    for (const station::PlanStep &s : m_plan.steps) {
        enabled += s.enabled ? 1 : 0;
        steps << (s.enabled ? tr("✓ %1") : tr("✗ %1 (off)")).arg(TestPlan::title(s.kind));
    }
    const QString file = m_planPath.isEmpty() ? tr("not saved") : QDir::toNativeSeparators(m_planPath);
    m_planName->setFullText(tr("%1 · %2 of %3 steps · %4")
                                .arg(m_plan.name.isEmpty() ? tr("(no name)") : m_plan.name)
                                .arg(enabled)
                                .arg(m_plan.steps.size())
                                .arg(file));
    m_planName->setExtraToolTip(steps.join(QLatin1Char('\n')));
}

void StationView::choosePlan()
{
    const QString start = m_planPath.isEmpty() ? QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation)
                                               : QFileInfo(m_planPath).absolutePath();
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open test plan"), start, tr("Station plans (*.json);;All files (*)"));
    if (!path.isEmpty())
        openPlan(path);
}

void StationView::newFromExample()
{
    setPlan(demoPlan(), QString());
    if (m_editor)
        m_editor->close();
    editPlan();
}

PlanEditorDialog *StationView::editPlan()
{
    if (m_editor) {
        m_editor->show();
        m_editor->raise();
        m_editor->activateWindow();
        return m_editor;
    }
    auto *editor = new PlanEditorDialog(m_havePlan ? m_plan : demoPlan(), m_planPath, this);
    editor->setAttribute(Qt::WA_DeleteOnClose);
    connect(editor, &QDialog::finished, editor, &QObject::deleteLater);
    connect(editor, &PlanEditorDialog::saved, this,
            [this](const TestPlan &plan, const QString &path) { setPlan(plan, path); });
    m_editor = editor;
    editor->show();
    return editor;
}

// ---------------------------------------------------------------- ports

void StationView::addPortItem(const QString &port, const QString &text, const QString &toolTip, bool checked)
{
    auto *item = new QListWidgetItem(text, m_ports);
    item->setData(Qt::UserRole, port);
    item->setToolTip(toolTip);
    item->setFlags((item->flags() | Qt::ItemIsUserCheckable) & ~Qt::ItemIsSelectable);
    item->setCheckState(checked ? Qt::Checked : Qt::Unchecked);
}

void StationView::refreshPorts()
{
    const QStringList checked = checkedPorts();
    const QSignalBlocker block(m_ports);
    m_ports->clear();
    for (const QSerialPortInfo &info : QSerialPortInfo::availablePorts()) {
        const QString port = info.systemLocation();
        QStringList tip{port};
        if (!info.description().isEmpty())
            tip << info.description();
        if (!info.manufacturer().isEmpty())
            tip << tr("Made by %1").arg(info.manufacturer());
        if (!info.serialNumber().isEmpty())
            tip << tr("Adapter serial number %1").arg(info.serialNumber());
        addPortItem(port, info.description().isEmpty() ? port : tr("%1 (%2)").arg(port, info.description()),
                    tip.join(QLatin1Char('\n')), checked.contains(port));
    }
    for (const QString &port : std::as_const(m_simPorts))
        addPortItem(port, tr("%1 (simulated)").arg(port), m_simNotes.value(port), checked.contains(port));
    updateActions();
}

QStringList StationView::checkedPorts() const
{
    QStringList ports;
    for (int i = 0; i < m_ports->count(); ++i)
        if (m_ports->item(i)->checkState() == Qt::Checked)
            ports << m_ports->item(i)->data(Qt::UserRole).toString();
    return ports;
}

void StationView::setPortChecked(const QString &port, bool checked)
{
    for (int i = 0; i < m_ports->count(); ++i)
        if (m_ports->item(i)->data(Qt::UserRole).toString() == port)
            m_ports->item(i)->setCheckState(checked ? Qt::Checked : Qt::Unchecked);
}

QStringList StationView::simulatedPorts() const
{
    return m_simPorts;
}

bool StationView::startSimulatedTray(int count, bool withFaults, QString *error)
{
    if (running()) {
        if (error)
            *error = tr("Wait for the run to end, or cancel it, before changing the simulated tray.");
        return false;
    }
    count = std::clamp(count, 1, int(kMaxTraySize));
    stopSimulatedTray();
    // The three faulty modules: spread over a tray of six or more, else the first ones.
    const auto faultAt = [count](int i) {
        const int step = count >= 6 ? 2 : 1, first = count >= 6 ? 1 : 0;
        if (i < first || (i - first) % step != 0)
            return -1;
        const int fault = (i - first) / step;
        return fault < 3 ? fault : -1;
    };
    for (int i = 0; i < count; ++i) {
        sim::SimOptions o;
        o.model = "HI14";
        o.firmware = "1.7.1";
        o.baud = kSimulatedBaud;
        o.seed = uint64_t(i + 1);
        o.faults.magCalFixture = true; // the tray turns every module while its MCAL collects
        QString note = tr("a good module");
        switch (withFaults ? faultAt(i) : -1) {
        case 0:
            o.faults.gyroNoiseFactor = sim::SimFaults::kNoisyGyroFactor;
            note = tr("a noisy gyro (%1 times the noise)").arg(sim::SimFaults::kNoisyGyroFactor);
            break;
        case 1:
            o.faults.mountingErrorDeg = {sim::SimFaults::kWrongMountingRollDeg, 0, 0};
            note = tr("mounted wrongly (on its side, roll %1°)").arg(sim::SimFaults::kWrongMountingRollDeg);
            break;
        case 2:
            o.firmware = "1.6.6";
            note = tr("old firmware");
            break;
        default: break;
        }
        auto sim = std::make_unique<sim::PtySimulator>(o);
        QString why;
        if (!sim->start(&why)) {
            stopSimulatedTray();
            if (error)
                *error = tr("The simulated modules could not start: %1").arg(why);
            return false;
        }
        const QString port = sim->devicePath();
        m_simPorts << port;
        m_simNotes.insert(port, tr("Simulated HI14 %1 of %2, firmware %3: %4")
                                    .arg(i + 1)
                                    .arg(count)
                                    .arg(QString::fromStdString(o.firmware), note));
        m_sims.push_back(std::move(sim));
    }
    refreshPorts();
    // The tray is what is tested now: only its ports are checked.
    for (int i = 0; i < m_ports->count(); ++i)
        m_ports->item(i)->setCheckState(m_simPorts.contains(m_ports->item(i)->data(Qt::UserRole).toString())
                                            ? Qt::Checked
                                            : Qt::Unchecked);
    updateActions();
    return true;
}

void StationView::stopSimulatedTray()
{
    for (auto &sim : m_sims)
        sim->stop();
    m_sims.clear();
    if (m_simPorts.isEmpty())
        return;
    const QStringList gone = m_simPorts;
    m_simPorts.clear();
    m_simNotes.clear();
    if (!m_ports)
        return;
    for (int i = m_ports->count() - 1; i >= 0; --i)
        if (gone.contains(m_ports->item(i)->data(Qt::UserRole).toString()))
            delete m_ports->takeItem(i);
    updateActions();
}

void StationView::openTrayDialog()
{
    // Non-modal: the station keeps running while it is open.
    auto *dialog = new QDialog(this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(tr("Simulated tray"));
    auto *count = new QSpinBox(dialog);
    count->setObjectName(QStringLiteral("trayCount"));
    count->setRange(1, kMaxTraySize);
    count->setValue(kDemoTraySize);
    auto *faults = new QCheckBox(tr("Three with faults: a noisy gyro, a wrong mounting, firmware 1.6.6"), dialog);
    faults->setObjectName(QStringLiteral("trayFaults"));
    faults->setChecked(true);
    auto *about = new QLabel(tr("Simulated HI14 modules on pseudo-terminals, each on a rotation fixture (for the "
                                "magnetometer calibration). They stop when this window closes."),
                             dialog);
    about->setWordWrap(true);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, dialog);
    auto *form = new QFormLayout;
    form->addRow(tr("Modules:"), count);
    auto *layout = new QVBoxLayout(dialog);
    layout->addWidget(about);
    layout->addLayout(form);
    layout->addWidget(faults);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::accepted, dialog, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::reject);
    connect(dialog, &QDialog::accepted, this, [this, count, faults] {
        QString error;
        if (!startSimulatedTray(count->value(), faults->isChecked(), &error))
            showError(error);
    });
    dialog->show();
}

// ---------------------------------------------------------------- report folder

QString StationView::reportFolder() const
{
    const QString dir = QDir::fromNativeSeparators(m_folder->text().trimmed());
    return dir.isEmpty() ? StationSettings::defaultReportFolder() : dir;
}

void StationView::setReportFolder(const QString &dir)
{
    m_folder->setText(QDir::toNativeSeparators(dir));
    if (dir != m_settings.reportFolder) {
        m_settings.reportFolder = dir;
        rememberSettings();
    }
}

void StationView::chooseReportFolder()
{
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Folder for the station's reports"), reportFolder());
    if (!dir.isEmpty())
        setReportFolder(dir);
}

// ---------------------------------------------------------------- the run

bool StationView::running() const
{
    return m_runner && m_runner->running();
}

int StationView::baudFor(const QString &port) const
{
    return m_simPorts.contains(port) ? kSimulatedBaud : m_runBaud;
}

bool StationView::start()
{
    if (running())
        return false;
    if (!m_havePlan) {
        showError(tr("Open a test plan first (Open…), or start from the example."));
        return false;
    }
    if (const QStringList problems = m_plan.problems(); !problems.isEmpty()) {
        showError(tr("The plan \"%1\" cannot run:\n• %2\nEdit it (Edit…) and start again.")
                      .arg(m_plan.name, problems.join(QStringLiteral("\n• "))));
        return false;
    }
    const QStringList ports = checkedPorts();
    if (ports.isEmpty()) {
        showError(tr("Check the ports of the modules to test first."));
        return false;
    }
    auto runner = std::make_unique<StationRunner>(m_plan, ports);
    // A tray of simulated modules is known to talk at 115200 baud; real ones are detected.
    const bool allSimulated =
        std::all_of(ports.begin(), ports.end(), [this](const QString &p) { return m_simPorts.contains(p); });
    m_runBaud = allSimulated ? kSimulatedBaud : 0;
    runner->setBaud(m_runBaud);
    QString error;
    const QString folder = station::RunFolder::newRunPath(reportFolder(), m_plan);
    if (!runner->setRunFolder(folder, &error)) {
        showError(tr("The report folder cannot be used: %1").arg(error));
        return false;
    }
    runner->setReportWriter(&writeStationReport);
    connect(runner.get(), &StationRunner::moduleFinished, this, &StationView::onModuleFinished);
    connect(runner.get(), &StationRunner::finished, this, [this] {
        m_model->refresh();
        showNewReportErrors();
        updateSummary();
        updateActions();
    });
    m_pendingOpen.clear();
    m_reportErrorsShown = 0;
    m_model->setRunner(runner.get()); // the tiles follow (modelReset)
    m_runner = std::move(runner);     // the previous run's runner (finished) goes
    m_runner->start();
    m_model->refresh();
    updateSummary();
    updateActions();
    return true;
}

void StationView::cancel()
{
    if (running())
        m_runner->cancel();
}

void StationView::rerunFailed()
{
    if (!m_runner)
        return;
    QList<int> failed;
    for (int i = 0; i < m_runner->moduleCount(); ++i)
        if (m_runner->module(i).verdict == Verdict::Fail)
            failed << i;
    if (failed.isEmpty())
        return;
    m_runner->rerun(failed);
    m_model->refresh();
    updateSummary();
    updateActions();
}

void StationView::onModuleFinished(int index)
{
    m_model->refresh(); // the tile shows the verdict at once
    showNewReportErrors();
    if (m_pendingOpen.remove(index) && m_runner) {
        // The module's session closes its port in its own thread: open the workspace a moment later.
        const QString port = m_runner->module(index).port;
        const int baud = baudFor(port);
        QTimer::singleShot(kPortReleaseMs, this, [this, port, baud] { Q_EMIT openWorkspaceRequested(port, baud); });
    }
    updateSummary();
    updateActions();
}

void StationView::showNewReportErrors()
{
    if (!m_runner)
        return;
    const QStringList &errors = m_runner->reportErrors();
    if (errors.size() <= m_reportErrorsShown)
        return;
    const QStringList fresh = errors.mid(m_reportErrorsShown);
    m_reportErrorsShown = int(errors.size());
    showError(tr("A report could not be written:\n%1").arg(fresh.join(QLatin1Char('\n'))));
}

void StationView::openModule(int index)
{
    if (!m_runner || index < 0 || index >= m_runner->moduleCount())
        return;
    const ModuleResult &r = m_runner->module(index);
    if (r.verdict == Verdict::Running) {
        // Its port is the station's until the test ends: the workspace opens then.
        m_pendingOpen.insert(index);
        updateSummary();
        return;
    }
    Q_EMIT openWorkspaceRequested(r.port, baudFor(r.port));
}

QString StationView::summaryText() const
{
    return m_summary->fullText();
}

QWidget *StationView::tile(int index) const
{
    return index >= 0 && index < int(m_tiles.size()) ? m_tiles[size_t(index)] : nullptr;
}

int StationView::tileColumns() const
{
    return m_grid->columns();
}

void StationView::rebuildTiles()
{
    for (StationTile *t : m_tiles)
        delete t; // its layout item goes with it
    m_tiles.clear();
    for (int i = 0; i < m_model->rowCount(); ++i) {
        auto *t = new StationTile(i, m_tileArea);
        t->activated = [this, i] { openModule(i); };
        m_grid->addWidget(t);
        m_tiles.push_back(t);
    }
    updateTiles(0, m_model->rowCount() - 1);
    m_placeholder->setVisible(m_tiles.empty());
    m_scroll->setVisible(!m_tiles.empty());
    updateSummary();
}

void StationView::updateTiles(int first, int last)
{
    for (int i = std::max(0, first); i <= last && i < int(m_tiles.size()); ++i) {
        const QModelIndex index = m_model->index(i);
        m_tiles[size_t(i)]->showModule(m_model->result(i), index.data(StationModel::StepRole).toString(),
                                       index.data(StationModel::VerdictTextRole).toString(),
                                       index.data(StationModel::FailureRole).toString(),
                                       index.data(Qt::ToolTipRole).toString());
    }
}

void StationView::updateSummary()
{
    if (!m_runner) {
        m_summary->setFullText(tr("No run yet."));
        m_summary->setExtraToolTip(QString());
        return;
    }
    const StationRunner::Summary s = m_runner->summary();
    QString text = tr("%1 passed · %2 failed · %3 running · %4 waiting")
                       .arg(s.passed)
                       .arg(s.failed)
                       .arg(s.running)
                       .arg(s.waiting);
    if (!m_pendingOpen.isEmpty()) {
        QList<int> waiting = m_pendingOpen.values();
        std::sort(waiting.begin(), waiting.end());
        QStringList ports;
        for (int i : waiting)
            ports << m_runner->module(i).port;
        text += ports.size() == 1
            ? tr(" — the workspace of %1 opens when its test has ended").arg(ports.first())
            : tr(" — the workspaces of %1 open when their tests have ended").arg(ports.join(QStringLiteral(", ")));
    }
    m_summary->setFullText(text);
    m_summary->setExtraToolTip(tr("Reports of this run: %1").arg(QDir::toNativeSeparators(m_runner->runFolder())));
}

void StationView::updateActions()
{
    if (!m_start)
        return;
    const bool busy = running();
    bool anyFailed = false;
    if (m_runner)
        for (int i = 0; i < m_runner->moduleCount(); ++i)
            anyFailed = anyFailed || m_runner->module(i).verdict == Verdict::Fail;
    m_start->setEnabled(!busy && m_havePlan && !checkedPorts().isEmpty());
    m_cancel->setEnabled(busy);
    m_rerun->setEnabled(anyFailed);
    m_tray->setEnabled(!busy);
}

} // namespace imudesk::ui
