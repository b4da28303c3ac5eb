#pragma once
/// \file frog_parameters_panel.h
/// The parameters of the active scene, and only those (docs/scenes.md): one row per key of the
/// scene's file, with the thesis's names and units, spin boxes wide enough in range for the
/// extreme cases of docs/extreme-cases.md. Every spin box is one number of the core's table
/// (parameterNumber, scene_parameters.h); an edit emits that number, and the tab sets it through
/// the core (withParameter, scene.h) and applies it live: no JSON on the way.

#include <QStringList>
#include <QWidget>

#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QGridLayout;
class QLabel;

namespace granota {
struct SceneSpec;
}

namespace granota::ui {

class FrogParametersPanel : public QWidget {
    Q_OBJECT
public:
    explicit FrogParametersPanel(QWidget* parent = nullptr);

    /// Builds the rows of `scene`'s parameters and shows its values.
    void setScene(const SceneSpec& scene);
    /// Shows `scene`'s values again (after an undo, or a refused edit); emits nothing.
    void setValues(const SceneSpec& scene);
    /// The keys shown, in the scene file's order (docs/scenes.md names: gravity, legs, …).
    QStringList keys() const { return m_keys; }
    /// The spin box `index` of `key` (0 for x / min / upper, 1 for y / max / lower, …), for tests.
    QDoubleSpinBox* spinBox(const QString& key, int index = 0) const;
    void retranslate();

signals:
    /// The number (`part`, `index`) of `key` was edited to `value` (withParameter's arguments; for
    /// the grab, `value` is the index of grabChoices()).
    void edited(const QString& key, int part, int index, double value);

protected:
    void changeEvent(QEvent* event) override;

private:
    int spinMinimumWidth() const;
    struct Field {
        QString key;
        QString sub;   ///< legs: front/back; angle_limits: the limit's name; chain: the link
        int part = 0;  ///< which leg pair, limit or link (parameterNumber's part)
        int index = 0; ///< which coordinate of it (parameterNumber's index)
        QDoubleSpinBox* spin = nullptr;
        double exact = 0; ///< the model's value, kept while the shown (rounded) one is untouched
        double shown = 0;
        double factor = 1; ///< shown = model × factor (degrees for radians)
    };
    struct Row {
        QString key, sub;
        QLabel* label = nullptr;
    };

    void clear();
    void addRow(const QString& key, const QString& sub, int part, int count, double factor);
    void fieldChanged(const Field& f);
    double modelValue(const Field& f) const;
    QString labelFor(const QString& key, const QString& sub) const;
    QString tipFor(const QString& key, const QString& sub) const;
    QString unitFor(const QString& key) const;

    QGridLayout* m_grid;
    QStringList m_keys;
    std::vector<Field> m_fields;
    std::vector<Row> m_rows;
    QComboBox* m_grab = nullptr;
    QLabel* m_fileOnly = nullptr;
    bool m_updating = false;
};

} // namespace granota::ui
