#pragma once
/// \file frog_parameters_panel.h
/// The parameters of the active scene, and only those (docs/scenes.md): one row per key of the
/// scene's file, with the thesis's names and units, spin boxes wide enough in range for the
/// extreme cases of docs/extreme-cases.md. An edit emits the key's whole new value (as the scene file
/// writes it); the tab validates it through the core and applies it live.

#include <QJsonObject>
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
    /// `key` was edited; `value` is its whole new value in the scene file's form.
    void edited(const QString& key, const QJsonValue& value);

protected:
    void changeEvent(QEvent* event) override;

private:
    int spinMinimumWidth() const;
    struct Field {
        QString key;
        QString sub;   ///< legs: front/back; angle_limits: the limit's name
        int index = 0; ///< position inside the key's value
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
    void addRow(const QString& key, const QString& sub, int count, double factor);
    void fieldChanged(const QString& key);
    double modelValue(const Field& f) const;
    QString labelFor(const QString& key, const QString& sub) const;
    QString tipFor(const QString& key, const QString& sub) const;
    QString unitFor(const QString& key) const;

    QGridLayout* m_grid;
    QStringList m_keys;
    QString m_model; ///< "pendulum" or other: the angle limits read differently
    std::vector<Field> m_fields;
    std::vector<Row> m_rows;
    QComboBox* m_grab = nullptr;
    QLabel* m_fileOnly = nullptr;
    QJsonObject m_values;
    bool m_updating = false;
};

} // namespace granota::ui
