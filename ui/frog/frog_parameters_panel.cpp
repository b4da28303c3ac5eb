#include "ui/frog/frog_parameters_panel.h"
#include "ui/common/decimal_spin_box.h"

#include "core/softbody/scenes/scene.h"
#include "ui/frog/frog_json.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QJsonArray>
#include <QEvent>
#include <QLabel>

#include <cmath>

namespace granota::ui {

namespace {

struct Range {
    double min, max;
    int decimals;
    double step;
};

/// Wide ranges on purpose: docs/extreme-cases.md lists huge gravity, target area 0 or huge, 3 to 200
/// sides and more; the core refuses what makes no sense, with a message.
Range rangeFor(const QString& key)
{
    if (key == QLatin1String("sides")) return {3, 10000, 0, 1};
    if (key == QLatin1String("bodies")) return {1, 1000, 0, 1};
    if (key == QLatin1String("bezier_samples")) return {3, 2000, 0, 1};
    if (key == QLatin1String("bezier_fit_degree")) return {1, 30, 0, 1};
    if (key == QLatin1String("radius")) return {0, 1e6, 1, 5};
    if (key == QLatin1String("center")) return {-1e6, 1e6, 1, 10};
    if (key == QLatin1String("width") || key == QLatin1String("height")) return {1, 100000, 0, 10};
    if (key == QLatin1String("gravity")) return {-1e6, 1e6, 2, 0.05};
    if (key == QLatin1String("v0")) return {-1e6, 1e6, 2, 0.5};
    if (key == QLatin1String("friction")) return {-10, 10, 3, 0.01};
    if (key == QLatin1String("velmax")) return {0, 1e9, 1, 1};
    if (key == QLatin1String("spring_length")) return {0, 1e6, 2, 1};
    if (key == QLatin1String("target_area")) return {0, 1e12, 0, 1000};
    if (key == QLatin1String("area_factor")) return {-1e6, 1e6, 3, 0.01};
    if (key == QLatin1String("angle_limits")) return {-3600, 3600, 1, 5};
    return {0, 1e4, 1, 5}; // legs, chain: lengths in px
}

bool isPair(const QString& key)
{
    return key == QLatin1String("center") || key == QLatin1String("gravity") || key == QLatin1String("v0") ||
           key == QLatin1String("friction");
}

const char* const kLimitOrder[] = {"shoulder_front_right", "shoulder_front_left", "shoulder_back_right",
                                   "shoulder_back_left",   "elbow_front",         "elbow_back",
                                   "shoulder",             "elbow"};

constexpr double kDegrees = 180.0 / M_PI;

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

void FrogParametersPanel::addRow(const QString& key, const QString& sub, int count, double factor)
{
    const int row = m_grid->rowCount();
    auto* label = new QLabel(this);
    label->setWordWrap(true);
    m_grid->addWidget(label, row, 0);
    m_rows.push_back({key, sub, label});
    const Range r = rangeFor(key);
    for (int i = 0; i < count; ++i) {
        auto* spin = new DecimalSpinBox(this);
        spin->setRange(r.min, r.max);
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
        f.index = i;
        f.spin = spin;
        f.factor = factor;
        m_fields.push_back(f);
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this, key] {
            if (!m_updating)
                fieldChanged(key);
        });
    }
}

void FrogParametersPanel::setScene(const SceneSpec& scene)
{
    clear();
    m_keys.clear();
    m_model = scene.model == SceneModel::Pendulum ? QStringLiteral("pendulum") : QString();
    const Json doc = sceneToJson(scene);
    const QJsonObject params = toQJson(*doc.find("params")).toObject();
    QStringList fileOnly;
    for (const std::string& k : scene.paramKeys) {
        const QString key = QString::fromStdString(k);
        m_keys << key;
        const QJsonValue value = params.value(key);
        if (key == QLatin1String("grab")) {
            const int row = m_grid->rowCount();
            auto* label = new QLabel(this);
            m_grid->addWidget(label, row, 0);
            m_rows.push_back({key, QString(), label});
            m_grab = new QComboBox(this);
            m_grab->setObjectName(QStringLiteral("param_grab"));
            m_grab->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
            m_grab->setMinimumContentsLength(8);
            for (const char* mode : {"all", "above", "anchors"})
                m_grab->addItem(QString(), QString::fromLatin1(mode));
            m_grid->addWidget(m_grab, row, 1, 1, 2);
            connect(m_grab, &QComboBox::currentIndexChanged, this, [this] {
                if (!m_updating)
                    emit edited(QStringLiteral("grab"), m_grab->currentData().toString());
            });
        } else if (key == QLatin1String("legs")) {
            addRow(key, QStringLiteral("front"), 2, 1);
            addRow(key, QStringLiteral("back"), 2, 1);
        } else if (key == QLatin1String("angle_limits")) {
            const QJsonObject limits = value.toObject();
            for (const char* name : kLimitOrder)
                if (limits.contains(QLatin1String(name)))
                    addRow(key, QString::fromLatin1(name), 2, kDegrees);
        } else if (key == QLatin1String("chain")) {
            const int links = value.toArray().size();
            for (int i = 0; i < links; ++i)
                addRow(key, QString::number(i), 1, 1);
        } else if (key == QLatin1String("obstacles") || key == QLatin1String("shapes")) {
            fileOnly << key;
        } else {
            addRow(key, QString(), isPair(key) ? 2 : 1, 1);
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
    const Json doc = sceneToJson(scene);
    m_values = toQJson(*doc.find("params")).toObject();
    for (Field& f : m_fields) {
        QJsonValue v = m_values.value(f.key);
        if (f.key == QLatin1String("chain"))
            v = v.toArray().at(f.sub.toInt());
        else if (!f.sub.isEmpty())
            v = v.toObject().value(f.sub);
        if (v.isArray())
            v = v.toArray().at(f.index);
        f.exact = v.toDouble();
        f.spin->setValue(f.exact * f.factor);
        f.shown = f.spin->value();
    }
    if (m_grab) {
        const int i = m_grab->findData(m_values.value(QStringLiteral("grab")).toString());
        m_grab->setCurrentIndex(std::max(0, i));
    }
    m_updating = false;
}

double FrogParametersPanel::modelValue(const Field& f) const
{
    // An untouched field gives back the model's own value (π stays π, 0.05 stays 0.05).
    return f.spin->value() == f.shown ? f.exact : f.spin->value() / f.factor;
}

void FrogParametersPanel::fieldChanged(const QString& key)
{
    QJsonValue value;
    if (key == QLatin1String("legs") || key == QLatin1String("angle_limits")) {
        QJsonObject o;
        for (const Field& f : m_fields)
            if (f.key == key) {
                QJsonArray pair = o.value(f.sub).toArray();
                while (pair.size() <= f.index)
                    pair.append(0.0);
                pair[f.index] = modelValue(f);
                o.insert(f.sub, pair);
            }
        value = o;
    } else if (key == QLatin1String("chain")) {
        QJsonArray links;
        for (const Field& f : m_fields)
            if (f.key == key)
                links.append(modelValue(f));
        value = links;
    } else if (isPair(key)) {
        QJsonArray pair;
        for (const Field& f : m_fields)
            if (f.key == key)
                pair.append(modelValue(f));
        value = pair;
    } else {
        for (const Field& f : m_fields)
            if (f.key == key)
                value = modelValue(f);
    }
    emit edited(key, value);
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
    if (key == QLatin1String("radius") || key == QLatin1String("center") || key == QLatin1String("width") ||
        key == QLatin1String("height") || key == QLatin1String("spring_length") || key == QLatin1String("legs") ||
        key == QLatin1String("chain"))
        return tr("px");
    if (key == QLatin1String("gravity"))
        return tr("px/step²");
    if (key == QLatin1String("v0") || key == QLatin1String("velmax"))
        return tr("px/step");
    if (key == QLatin1String("target_area"))
        return tr("px²");
    if (key == QLatin1String("angle_limits"))
        return QStringLiteral("°");
    return {};
}

QString FrogParametersPanel::labelFor(const QString& key, const QString& sub) const
{
    if (key == QLatin1String("sides")) return tr("Sides N");
    if (key == QLatin1String("radius")) return tr("Radius r");
    if (key == QLatin1String("center")) return tr("Centre (x, y)");
    if (key == QLatin1String("width")) return tr("Frame width");
    if (key == QLatin1String("height")) return tr("Frame height");
    if (key == QLatin1String("gravity")) return tr("Gravity g (x, y)");
    if (key == QLatin1String("v0")) return tr("Initial velocity v₀ (x, y)");
    if (key == QLatin1String("friction")) return tr("Friction f (x, y)");
    if (key == QLatin1String("velmax")) return tr("Largest move velmax");
    if (key == QLatin1String("spring_length")) return tr("Spring length");
    if (key == QLatin1String("target_area")) return tr("Target area");
    if (key == QLatin1String("area_factor")) return tr("Area factor C");
    if (key == QLatin1String("grab")) return tr("Grab");
    if (key == QLatin1String("bodies")) return tr("Bodies");
    if (key == QLatin1String("bezier_samples")) return tr("Bézier points");
    if (key == QLatin1String("bezier_fit_degree")) return tr("Fit degree n");
    if (key == QLatin1String("legs"))
        return sub == QLatin1String("front") ? tr("Front legs (upper, lower)") : tr("Back legs (upper, lower)");
    if (key == QLatin1String("chain")) return tr("Link %1").arg(sub.toInt() + 1);
    if (key == QLatin1String("angle_limits")) {
        if (sub == QLatin1String("shoulder_front_right")) return tr("Front right shoulder (min, max)");
        if (sub == QLatin1String("shoulder_front_left")) return tr("Front left shoulder (min, max)");
        if (sub == QLatin1String("shoulder_back_right")) return tr("Back right shoulder (min, max)");
        if (sub == QLatin1String("shoulder_back_left")) return tr("Back left shoulder (min, max)");
        if (sub == QLatin1String("elbow_front")) return tr("Front elbows (min, max)");
        if (sub == QLatin1String("elbow_back")) return tr("Back elbows (min, max)");
        if (sub == QLatin1String("shoulder")) return tr("Shoulder (min, max)");
        if (sub == QLatin1String("elbow")) return tr("Elbow (min, max)");
    }
    return key;
}

QString FrogParametersPanel::tipFor(const QString& key, const QString& sub) const
{
    if (key == QLatin1String("sides"))
        return tr("N (costats): the vertices of the body, a regular polygon built from the top (§4.1). "
                  "Annex II's frog has N = 10; try 3 to 200. Up to 10000, 100000 vertices in all: beyond about 3000 "
                  "the stable solver runs slower than real time.");
    if (key == QLatin1String("radius"))
        return tr("r: distance from the centre to each vertex of the starting polygon (§4.1).");
    if (key == QLatin1String("center"))
        return tr("(c₁, c₂): where the first body starts, in pixels of the frame (y grows downwards).");
    if (key == QLatin1String("width") || key == QLatin1String("height"))
        return tr("The frame (Processing's size(1280, 720)): vertices stay inside [0, width − 1] × [0, height − 1] (§4.2).");
    if (key == QLatin1String("gravity"))
        return tr("g (gravetat): acceleration added to every vertex each step, v(t) = v(t − 1) + g (§4.2).");
    if (key == QLatin1String("v0"))
        return tr("v⁰ (velocitat inicial): the velocity the body starts with (§4.2).");
    if (key == QLatin1String("friction"))
        return tr("f (fregament): share of the velocity kept per step on each axis, f ∈ ]0, 1[ (§4.3).");
    if (key == QLatin1String("velmax"))
        return tr("velmax: the largest move of a vertex in one step, per axis (Annex II).");
    if (key == QLatin1String("spring_length"))
        return tr("molls: rest length of every edge spring; the springs pull the edges back towards it (§4.4).");
    if (key == QLatin1String("target_area"))
        return tr("Areal: the area the body tries to keep, by the trapezoid rule and edge normals (§4.5). "
                  "0 or huge values are allowed.");
    if (key == QLatin1String("area_factor"))
        return tr("C (reescala): how strongly each step corrects the area; large values make a stiff body (§4.5).");
    if (key == QLatin1String("grab"))
        return tr("Which vertices hold on to the mouse: all of them (§4.6), those above the grab point (§4.7), "
                  "or Annex II's fixed anchors {0, 1, N−1, N} (§4.10).");
    if (key == QLatin1String("bodies"))
        return tr("How many bodies fall and collide (§5.2.2); a broad phase keeps the cost close to linear.");
    if (key == QLatin1String("bezier_samples"))
        return tr("§4.9: the polygon is the control polygon of one Bézier curve, sampled once at this many points by "
                  "De Casteljau (Def 2.4); the samples become the body's vertices.");
    if (key == QLatin1String("bezier_fit_degree"))
        return tr("§4.9, the abandoned option: the degree n of the least-squares Bézier curve fitted to the outline "
                  "every frame (Lemma 2.2, Prop 2.2).");
    if (key == QLatin1String("legs"))
        return tr("longit: lengths of the two segments of each leg, shoulder–elbow and elbow–wrist (§4.16, Annex II).");
    if (key == QLatin1String("chain"))
        return tr("Length of this link of the pendulum; the links keep their length exactly (§4.13, §4.14).");
    if (key == QLatin1String("angle_limits"))
        return sub.startsWith(QLatin1String("elbow"))
                   ? tr("angles: smallest and largest angle between the two segments at the elbow, in degrees "
                        "(§4.15; Annex II uses ±π/12 in front, ±π/3 behind).")
                   : tr("anglesc: smallest and largest angle of the upper segment at the shoulder, in degrees "
                        "(§4.15; Annex II uses 0 to π and −π to 0).");
    return {};
}

void FrogParametersPanel::retranslate()
{
    for (const Row& r : m_rows) {
        r.label->setText(labelFor(r.key, r.sub));
        r.label->setToolTip(tipFor(r.key, r.sub));
    }
    for (const Field& f : m_fields) {
        const QString unit = unitFor(f.key);
        f.spin->setSuffix(unit.isEmpty() ? QString() : QStringLiteral(" ") + unit);
        f.spin->setToolTip(tipFor(f.key, f.sub));
    }
    if (m_grab) {
        m_grab->setItemText(0, tr("All vertices (§4.6)"));
        m_grab->setItemText(1, tr("Vertices above the mouse (§4.7)"));
        m_grab->setItemText(2, tr("Fixed anchors {0, 1, N−1, N} (§4.10)"));
        m_grab->setToolTip(tipFor(QStringLiteral("grab"), QString()));
    }
    if (m_fileOnly) {
        const QStringList keys = m_fileOnly->property("keys").toStringList();
        m_fileOnly->setText(keys.contains(QLatin1String("obstacles"))
                                ? tr("The obstacles come from the scene file.")
                                : tr("The shapes of the bodies come from the scene file."));
    }
}

} // namespace granota::ui
