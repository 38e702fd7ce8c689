#include "configuration/mounting_picker.h"

#include "model/mounting.h"
#include "configuration/mounting_tile.h"
#include "protocol/hipnuc/ascii_command.h"

#include "common/work_place_size.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGuiApplication>
#include <QLabel>
#include <QScreen>
#include <QScrollArea>
#include <QVBoxLayout>

#include <algorithm>

namespace imudesk::ui {

using settings::MountingChoice;
using Dir = MountingChoice::Direction;

namespace {
constexpr Dir kDirections[] = {Dir::Right, Dir::Left, Dir::Forward, Dir::Back, Dir::Up, Dir::Down};
}

MountingPicker::MountingPicker(int currentCode, bool legacyMatrix, QWidget *parent)
    : QDialog(parent), m_code(model::Mounting::isValidCode(currentCode) ? currentCode : model::Mounting::kDefaultCode),
      m_legacy(legacyMatrix)
{
    setWindowTitle(tr("Mounting (URFR)"));
    auto *layout = new QVBoxLayout(this);
    auto *intro = new QLabel(tr("Where do the module's axes point on the body (right, forward, up)? Pick a picture, a "
                                "code, or the directions of IMU X and IMU Y. The setting takes effect after "
                                "SAVECONFIG and a reset."),
                             this);
    intro->setWordWrap(true);
    layout->addWidget(intro);

    auto *form = new QFormLayout;
    m_codeBox = new QComboBox(this);
    for (int code : model::Mounting::validCodes())
        m_codeBox->addItem(QStringLiteral("%1 — %2")
                               .arg(QString::fromStdString(model::Mounting::codeText(code)),
                                    MountingChoice::description(code)),
                           code);
    form->addRow(tr("Code:"), m_codeBox);
    m_xBox = new QComboBox(this);
    m_yBox = new QComboBox(this);
    for (Dir d : kDirections) {
        m_xBox->addItem(MountingChoice::directionName(d), int(d));
        m_yBox->addItem(MountingChoice::directionName(d), int(d));
    }
    form->addRow(tr("IMU X points:"), m_xBox);
    form->addRow(tr("IMU Y points:"), m_yBox);
    m_zLabel = new QLabel(this);
    form->addRow(tr("IMU Z points:"), m_zLabel);
    layout->addLayout(form);
    m_error = new QLabel(this);
    m_error->setStyleSheet(QStringLiteral("color: #c62828"));
    m_error->setWordWrap(true);
    layout->addWidget(m_error);

    // The 24 pictures in 6 columns of 4, or 8 of 3 on a screen too low for four rows (a
    // 1366x768 laptop): each at least MountingTile::readableSize(), all in sight at once; the
    // scroll area only for a screen smaller still.
    const QScreen *screen = parent ? parent->screen() : QGuiApplication::primaryScreen();
    const int columns = screen && screen->availableGeometry().height() < 900 ? 8 : 6;
    auto *grid = new QGridLayout;
    int i = 0;
    for (int code : model::Mounting::validCodes()) {
        auto *t = new MountingTile(code, this);
        t->setToolTip(MountingChoice::description(code));
        connect(t, &MountingTile::clicked, this, [this](int c) { setCode(c); });
        m_tiles[code] = t;
        grid->addWidget(t, i / columns, i % columns);
        ++i;
    }
    auto *tiles = new QWidget(this);
    tiles->setLayout(grid);
    m_scroll = new QScrollArea(this);
    m_scroll->setWidget(tiles);
    m_scroll->setWidgetResizable(true);
    m_scroll->setFrameShape(QFrame::NoFrame);
    layout->addWidget(m_scroll, 1);

    m_description = new QLabel(this);
    m_command = new QLabel(this);
    m_command->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_description);
    layout->addWidget(m_command);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);

    connect(m_codeBox, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (!m_updating && index >= 0)
            setCode(m_codeBox->itemData(index).toInt());
    });
    connect(m_xBox, &QComboBox::currentIndexChanged, this, &MountingPicker::onDirectionsEdited);
    connect(m_yBox, &QComboBox::currentIndexChanged, this, &MountingPicker::onDirectionsEdited);
    refresh();
    // Large enough for every picture at its preferred size (a scroll area asks for less), on
    // the screen it opens on.
    layout->activate();
    const QSize pictures = tiles->sizeHint();
    const QSize rest = layout->sizeHint() - m_scroll->sizeHint();
    fitWorkPlace(this, QSize(std::max(layout->sizeHint().width(), pictures.width() + 2 * layout->contentsMargins().left()),
                             rest.height() + pictures.height() + 4),
                 parent);
}

bool MountingPicker::setCode(int code)
{
    if (!model::Mounting::isValidCode(code))
        return false;
    const bool changed = code != m_code;
    m_code = code;
    m_error->clear();
    refresh();
    if (changed)
        Q_EMIT codeChanged(code);
    return true;
}

bool MountingPicker::setDirections(Dir x, Dir y)
{
    m_updating = true;
    m_xBox->setCurrentIndex(m_xBox->findData(int(x)));
    m_yBox->setCurrentIndex(m_yBox->findData(int(y)));
    m_updating = false;
    onDirectionsEdited();
    return m_error->text().isEmpty();
}

void MountingPicker::onDirectionsEdited()
{
    if (m_updating)
        return;
    QString error;
    const auto code = MountingChoice::codeFor(Dir(m_xBox->currentData().toInt()), Dir(m_yBox->currentData().toInt()),
                                              std::nullopt, &error);
    if (!code) {
        m_error->setText(error);
        m_zLabel->setText(tr("(no right-handed mounting)"));
        return;
    }
    setCode(*code);
}

void MountingPicker::refresh()
{
    m_updating = true;
    m_codeBox->setCurrentIndex(m_codeBox->findData(m_code));
    const auto axes = MountingChoice::axesOfCode(m_code);
    m_xBox->setCurrentIndex(m_xBox->findData(int(axes.x)));
    m_yBox->setCurrentIndex(m_yBox->findData(int(axes.y)));
    m_zLabel->setText(MountingChoice::directionName(axes.z));
    m_updating = false;
    for (auto &[code, tile] : m_tiles)
        tile->setChecked(code == m_code);
    m_description->setText(MountingChoice::description(m_code));
    m_command->setText(tr("Command: %1").arg(commandText()));
}

QString MountingPicker::value() const
{
    return QString::fromStdString(model::Mounting::codeText(m_code));
}

QString MountingPicker::commandText() const
{
    const auto c = m_legacy ? protocol::hipnuc::commands::imuUrfrMatrix(model::Mounting::legacyMatrixForCode(m_code))
                            : protocol::hipnuc::commands::imuUrfr(m_code);
    return QString::fromStdString(c.text);
}

QString MountingPicker::errorText() const
{
    return m_error->text();
}

MountingTile *MountingPicker::tile(int code) const
{
    const auto it = m_tiles.find(code);
    return it == m_tiles.end() ? nullptr : it->second;
}

} // namespace imudesk::ui
