#include "ui/frog/frog_parameters_panel.h"
#include "ui/common/decimal_spin_box.h"

#include "core/base/math_constants.h"
#include "core/softbody/scenes/scene.h"
#include "core/softbody/scenes/scene_parameters.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QEvent>
#include <QLabel>

#include <algorithm>
#include <cmath>

namespace granota::ui {

namespace {

/// The key's row of the core's table (core/softbody/scenes/scene_parameters.h); every key a scene
/// has is in it (the core refuses others).
const SceneParameter& parameter(const QString& key)
{
    static const SceneParameter none;
    const SceneParameter* p = findSceneParameter(key.toStdString());
    return p ? *p : none;
}

/// The table's English text in the panel's translation context.
QString translated(const char* text) { return QCoreApplication::translate(kParameterPanelContext, text); }

constexpr double kDegrees = 180.0 / kPi;

} // namespace

FrogParametersPanel::FrogParametersPanel(QWidget* parent) : QWidget(parent), m_grid(new QGridLayout(this))
{
    m_grid->setContentsMargins(0, 0, 0, 0);
    m_grid->setColumnStretch(1, 1);
    m_grid->setColumnStretch(2, 1);
    m_grid->setColumnMinimumWidth(0, fontMetrics().averageCharWidth() * 15);
}

void FrogParametersPanel::clear()
{
    while (QLayoutItem* item = m_grid->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    m_fields.clear();
    m_rows.clear();
    m_grab = nullptr;
    m_fileOnly = nullptr;
}

void FrogParametersPanel::addRow(const QString& key, const QString& sub, int part, int count, double factor)
{
    const int row = m_grid->rowCount();
    auto* label = new QLabel(this);
    label->setWordWrap(true);
    m_grid->addWidget(label, row, 0);
    m_rows.push_back({key, sub, label});
    const SpinRange r = parameter(key).spin;
    for (int i = 0; i < count; ++i) {
        auto* spin = new DecimalSpinBox(this);
        spin->setRange(r.lowest(), r.max);
        spin->setDecimals(r.decimals);
        spin->setSingleStep(r.step);
        spin->setKeyboardTracking(false); // apply on Enter or when leaving the field, not per digit
        spin->setAccelerated(true);
        // The range's longest number would make the box very wide: let the layout decide.
        spin->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
        spin->setMinimumWidth(spinMinimumWidth());
        spin->setObjectName(QStringLiteral("param_%1_%2_%3").arg(key, sub).arg(i));
        if (count == 1)
            m_grid->addWidget(spin, row, 1, 1, 2);
        else
            m_grid->addWidget(spin, row, 1 + i);
        Field f;
        f.key = key;
        f.sub = sub;
        f.part = part;
        f.index = i;
        f.spin = spin;
        f.factor = factor;
        m_fields.push_back(f);
        const std::size_t at = m_fields.size() - 1;
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this, at] {
            if (!m_updating)
                fieldChanged(m_fields[at]);
        });
    }
}

void FrogParametersPanel::setScene(const SceneSpec& scene)
{
    clear();
    m_keys.clear();
    QStringList fileOnly;
    for (const std::string& k : scene.paramKeys) {
        const QString key = QString::fromStdString(k);
        m_keys << key;
        switch (parameter(key).type) {
        case ParameterType::Choice: {
            const int row = m_grid->rowCount();
            auto* label = new QLabel(this);
            m_grid->addWidget(label, row, 0);
            m_rows.push_back({key, QString(), label});
            m_grab = new QComboBox(this);
            m_grab->setObjectName(QStringLiteral("param_grab"));
            m_grab->setProperty("key", key);
            m_grab->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
            m_grab->setMinimumContentsLength(8);
            for (const GrabChoice& choice : grabChoices())
                m_grab->addItem(QString(), QString::fromLatin1(choice.name));
            m_grid->addWidget(m_grab, row, 1, 1, 2);
            connect(m_grab, &QComboBox::currentIndexChanged, this, [this, key] {
                if (!m_updating)
                    emit edited(key, 0, 0, m_grab->currentIndex()); // the box lists grabChoices() in order
            });
            break;
        }
        case ParameterType::Legs:
            for (int part = 0; part < parameterPartCount(scene, parameter(key)); ++part)
                addRow(key, QString::fromLatin1(legParts()[static_cast<std::size_t>(part)].name), part, 2, 1);
            break;
        case ParameterType::AngleLimits:
            for (int part = 0; part < parameterPartCount(scene, parameter(key)); ++part)
                addRow(key, QString::fromLatin1(angleLimitOf(scene, part)->name), part, 2, kDegrees);
            break;
        case ParameterType::Chain:
            for (int link = 0; link < parameterPartCount(scene, parameter(key)); ++link)
                addRow(key, QString::number(link), link, 1, 1);
            break;
        case ParameterType::Obstacles:
        case ParameterType::Shapes: fileOnly << key; break;
        case ParameterType::Pair: addRow(key, QString(), 0, 2, 1); break;
        case ParameterType::Integer:
        case ParameterType::Number: addRow(key, QString(), 0, 1, 1); break;
        }
    }
    if (!fileOnly.isEmpty()) {
        m_fileOnly = new QLabel(this);
        m_fileOnly->setWordWrap(true);
        m_fileOnly->setProperty("keys", fileOnly);
        m_grid->addWidget(m_fileOnly, m_grid->rowCount(), 0, 1, 3);
    }
    retranslate();
    setValues(scene);
}

void FrogParametersPanel::setValues(const SceneSpec& scene)
{
    m_updating = true;
    for (Field& f : m_fields) {
        // The model's own number (a radius or centre derived from the frame included).
        f.exact = parameterNumber(scene, parameter(f.key), f.part, f.index);
        f.spin->setValue(f.exact * f.factor);
        f.shown = f.spin->value();
    }
    if (m_grab)
        m_grab->setCurrentIndex(static_cast<int>(parameterNumber(scene, parameter(m_grab->property("key").toString()), 0, 0)));
    m_updating = false;
}

double FrogParametersPanel::modelValue(const Field& f) const
{
    // An untouched field gives back the model's own value (π stays π, 0.05 stays 0.05).
    return f.spin->value() == f.shown ? f.exact : f.spin->value() / f.factor;
}

void FrogParametersPanel::fieldChanged(const Field& f)
{
    const QString key = f.key; // a copy: the tab's answer may build the rows again
    emit edited(key, f.part, f.index, modelValue(f));
}

int FrogParametersPanel::spinMinimumWidth() const
{
    return fontMetrics().horizontalAdvance(QStringLiteral("-00.00 px/step²")) + 22;
}

void FrogParametersPanel::changeEvent(QEvent* event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange) { // presentation mode: larger text, wider fields
        for (const Field& f : m_fields)
            f.spin->setMinimumWidth(spinMinimumWidth());
        m_grid->setColumnMinimumWidth(0, fontMetrics().averageCharWidth() * 15);
    }
}

QDoubleSpinBox* FrogParametersPanel::spinBox(const QString& key, int index) const
{
    int seen = 0;
    for (const Field& f : m_fields)
        if (f.key == key && seen++ == index)
            return f.spin;
    return nullptr;
}

QString FrogParametersPanel::unitFor(const QString& key) const
{
    const char* unit = parameter(key).unit;
    return *unit ? translated(unit) : QString();
}

QString FrogParametersPanel::labelFor(const QString& key, const QString& sub) const
{
    const SceneParameter& p = parameter(key);
    switch (p.type) {
    case ParameterType::Chain: return translated(p.label).arg(sub.toInt() + 1);
    case ParameterType::Legs:
        for (const ParameterPart& part : legParts())
            if (sub == QLatin1String(part.name))
                return translated(part.label);
        break;
    case ParameterType::AngleLimits:
        for (const AngleLimitParameter& limit : angleLimits())
            if (sub == QLatin1String(limit.name))
                return translated(limit.label);
        break;
    default:
        if (*p.label)
            return translated(p.label);
    }
    return key;
}

QString FrogParametersPanel::tipFor(const QString& key, const QString& sub) const
{
    const SceneParameter& p = parameter(key);
    if (p.type == ParameterType::AngleLimits) {
        for (const AngleLimitParameter& limit : angleLimits())
            if (sub == QLatin1String(limit.name))
                return translated(limit.tip);
        return {};
    }
    return *p.tip ? translated(p.tip) : QString();
}

void FrogParametersPanel::retranslate()
{
    for (const Row& r : m_rows) {
        r.label->setText(labelFor(r.key, r.sub));
        r.label->setToolTip(tipFor(r.key, r.sub));
    }
    for (const Field& f : m_fields) {
        // The name a screen reader gives the field: its row's label, and which coordinate.
        const auto parts = std::count_if(m_fields.begin(), m_fields.end(),
                                         [&f](const Field& g) { return g.key == f.key && g.sub == f.sub; });
        const QString label = labelFor(f.key, f.sub);
        f.spin->setAccessibleName(parts == 2  ? tr("%1, %2").arg(label, f.index == 0 ? QStringLiteral("x") : QStringLiteral("y"))
                                   : parts > 2 ? tr("%1, %2").arg(label).arg(f.index + 1)
                                              : label);
        const QString unit = unitFor(f.key);
        f.spin->setSuffix(unit.isEmpty() ? QString() : QStringLiteral(" ") + unit);
        f.spin->setToolTip(tipFor(f.key, f.sub));
    }
    if (m_grab) {
        for (int i = 0; i < m_grab->count(); ++i)
            m_grab->setItemText(i, translated(grabChoices()[static_cast<std::size_t>(i)].label));
        m_grab->setToolTip(tipFor(m_grab->property("key").toString(), QString()));
        m_grab->setAccessibleName(labelFor(m_grab->property("key").toString(), QString()));
    }
    if (m_fileOnly) {
        // One note: that of the first file-only key in the table's order (obstacles before shapes).
        const QStringList keys = m_fileOnly->property("keys").toStringList();
        for (const SceneParameter& p : sceneParameters())
            if (keys.contains(QLatin1String(p.key))) {
                m_fileOnly->setText(translated(p.fileNote));
                break;
            }
    }
}

} // namespace granota::ui
