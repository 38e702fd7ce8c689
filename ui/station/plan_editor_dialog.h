#pragma once
// Edits a production test plan (station/test_plan.h): its name, its steps in order (the check
// box turns a step on or off; Up, Down, Add, Remove) and, for the step selected, its
// description and a form made from the step kind's parameter catalogue (TestPlan::params):
// a number as a spin box with its unit and range, a text as a line, a file (firmware image,
// profile) with Browse…, kept relative to the plan's folder when it is inside it. What keeps
// the plan from running (TestPlan::problems(), and a number being typed outside its range)
// is listed under the form as it changes. Save (Ctrl+S) and Save as… write the JSON; a saved
// plan is announced with saved(). Non-modal.
//
// A pass/fail limit (ParamSpec::limit) has beside it a "Marginal band" check box and a second
// spin box for the band (plan format 2): values past the band, up to the limit, pass marked
// marginal. A plan read in an older format says so above the steps (it is saved in the new one).
#include "core/station/test_plan.h"

#include <QDialog>
#include <QMap>

class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QListWidgetItem;
class QPushButton;
class QToolButton;
class QWidget;

namespace imudesk::ui {

class PlanEditorDialog : public QDialog {
    Q_OBJECT

public:
    // `path` is where the plan was loaded from (empty: a new plan, Save asks where).
    PlanEditorDialog(station::TestPlan plan, QString path, QWidget *parent = nullptr);

    const station::TestPlan &plan() const { return m_plan; }
    const QString &path() const { return m_path; }
    bool isModified() const { return m_modified; }
    // What is listed under the form: the plan's problems and the values being typed out of range.
    QStringList problems() const;

    int currentStep() const;
    void selectStep(int index);
    // The form's field for a parameter of the selected step (tests): a QDoubleSpinBox or a QLineEdit.
    QWidget *field(const QString &key) const;

    // Writes the plan to path(); without one it asks where (Save as).
    bool save();
    bool saveAs();
    // Writes the plan to `path` (false, and the reason shown, when it cannot). A plan saved into
    // another folder keeps its files: relative paths are made relative to the new folder.
    bool saveTo(const QString &path);
    // Whether a step parameter names a file (relative to the plan's folder).
    static bool isPathParam(station::StepKind kind, const QString &key);
    // Close, Esc and the window's close button: unsaved changes are offered for saving first.
    void reject() override;

Q_SIGNALS:
    void saved(const imudesk::station::TestPlan &plan, const QString &path);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    void fillSteps();
    QString stepItemText(int index) const;
    void buildForm();
    QWidget *numberField(int step, const station::ParamSpec &spec);
    // The limit's spin box with its marginal band control beside it.
    QWidget *limitField(int step, const station::ParamSpec &spec, QDoubleSpinBox *limit);
    // Lists a value typed into `spin` that it will not take (out of range, not a number) under
    // problemKey while it is typed; `band`: the spin box is a limit's marginal band.
    void watchTyped(QDoubleSpinBox *spin, int step, const station::ParamSpec &spec, const QString &problemKey,
                    bool band);
    QWidget *textField(int step, const station::ParamSpec &spec);
    void browse(int step, const QString &key, QLineEdit *edit);
    void addStep(station::StepKind kind);
    void removeStep();
    void moveStep(int delta);
    void onItemChanged(QListWidgetItem *item);
    void setModified();
    void updateProblems();
    void updateTitle();
    void updateButtons();
    void updateConversionNote();
    void showError(const QString &message);
    // A path relative to `dir` when the file is inside it, else absolute.
    static QString relativeIfInside(const QString &absolute, const QString &dir);

    station::TestPlan m_plan;
    QString m_path;
    bool m_modified = false;
    bool m_filling = false;                // the list or the form is being filled, not edited
    QMap<QString, QString> m_typedProblems; // key (marginal_<key>: a band) -> why, for the selected step's spin boxes

    QLabel *m_nameLabel = nullptr;
    QLineEdit *m_name = nullptr;
    QLabel *m_conversionNote = nullptr; // a plan read in an older format: converted, saved in the new one
    QLabel *m_stepsLabel = nullptr;
    QListWidget *m_steps = nullptr;
    QPushButton *m_up = nullptr;
    QPushButton *m_down = nullptr;
    QToolButton *m_add = nullptr;
    QPushButton *m_remove = nullptr;
    QLabel *m_stepTitle = nullptr;
    QLabel *m_description = nullptr;
    QWidget *m_formHost = nullptr;
    QWidget *m_form = nullptr;
    QLabel *m_problems = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
    QPushButton *m_save = nullptr;
    QPushButton *m_saveAs = nullptr;
};

} // namespace imudesk::ui
