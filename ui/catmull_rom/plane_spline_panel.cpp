#include "ui/catmull_rom/plane_spline_panel.h"

#include "ui/common/number_text.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>

namespace granota::ui {

namespace {
constexpr std::array<ParametricEnds, 4> kPanelEnds{ParametricEnds::Natural, ParametricEnds::Clamped, ParametricEnds::NotAKnot,
                                                   ParametricEnds::Periodic};
constexpr std::array<SplineParameters, 3> kPanelParameters{SplineParameters::Uniform, SplineParameters::Chord,
                                                           SplineParameters::Centripetal};
} // namespace

PlaneSplinePanel::PlaneSplinePanel(QWidget* parent) : QWidget(parent)
{
    m_endsLabel = new QLabel(this);
    m_endsCombo = new QComboBox(this);
    m_parametersLabel = new QLabel(this);
    m_parametersCombo = new QComboBox(this);
    for (std::size_t i = 0; i < kPanelEnds.size(); ++i)
        m_endsCombo->addItem(QString());
    for (std::size_t i = 0; i < kPanelParameters.size(); ++i)
        m_parametersCombo->addItem(QString());
    m_endsLabel->setBuddy(m_endsCombo);
    m_parametersLabel->setBuddy(m_parametersCombo);
    m_startLabel = new QLabel(this);
    m_endLabel = new QLabel(this);
    for (QLineEdit*& edit : m_tangentEdits)
        edit = new QLineEdit(this);
    m_startLabel->setBuddy(m_tangentEdits[0]);
    m_endLabel->setBuddy(m_tangentEdits[2]);
    m_catmullRomCheck = new QCheckBox(this);
    m_error = new QLabel(this);
    m_error->setWordWrap(true);
    m_error->setStyleSheet(QStringLiteral("color: #c62828;"));

    auto* layout = new QGridLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_endsLabel, 0, 0);
    layout->addWidget(m_endsCombo, 0, 1, 1, 2);
    layout->addWidget(m_parametersLabel, 1, 0);
    layout->addWidget(m_parametersCombo, 1, 1, 1, 2);
    layout->addWidget(m_startLabel, 2, 0);
    layout->addWidget(m_tangentEdits[0], 2, 1);
    layout->addWidget(m_tangentEdits[1], 2, 2);
    layout->addWidget(m_endLabel, 3, 0);
    layout->addWidget(m_tangentEdits[2], 3, 1);
    layout->addWidget(m_tangentEdits[3], 3, 2);
    layout->addWidget(m_catmullRomCheck, 4, 0, 1, 3);
    layout->addWidget(m_error, 5, 0, 1, 3);
    layout->setColumnStretch(1, 1);
    layout->setColumnStretch(2, 1);

    connect(m_endsCombo, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (m_showing || i < 0)
            return;
        PlaneSplineSettings after = m_settings;
        after.ends = kPanelEnds[static_cast<std::size_t>(i)];
        emit changeRequested(after, tr("C² spline ends"));
    });
    connect(m_parametersCombo, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (m_showing || i < 0)
            return;
        PlaneSplineSettings after = m_settings;
        after.parameters = kPanelParameters[static_cast<std::size_t>(i)];
        emit changeRequested(after, tr("C² spline parameters"));
    });
    for (QLineEdit* edit : m_tangentEdits)
        connect(edit, &QLineEdit::editingFinished, this, &PlaneSplinePanel::tangentTyped);
    connect(m_catmullRomCheck, &QCheckBox::toggled, this, [this](bool on) {
        if (m_showing)
            return;
        PlaneSplineSettings after = m_settings;
        after.catmullRomToo = on;
        emit changeRequested(after, tr("Catmull-Rom comparison"));
    });
    retranslate();
}

void PlaneSplinePanel::tangentTyped()
{
    if (m_showing)
        return;
    std::array<Rational, 4> values;
    for (std::size_t i = 0; i < values.size(); ++i) {
        const auto v = parseTypedRational(m_tangentEdits[i]->text());
        if (!v || abs(*v) > PlaneSplineSettings::kMaxTangentAbs) {
            emit refused(tr("A tangent component is a number between −%1 and %1, such as 1/2 or -0.25.")
                             .arg(displayNumber(PlaneSplineSettings::kMaxTangentAbs)));
            m_tangentEdits[i]->setText(rationalText(i == 0   ? m_settings.startTangent.x
                                                    : i == 1 ? m_settings.startTangent.y
                                                    : i == 2 ? m_settings.endTangent.x
                                                             : m_settings.endTangent.y));
            return;
        }
        values[i] = *v;
    }
    PlaneSplineSettings after = m_settings;
    after.startTangent = RPoint(values[0], values[1]);
    after.endTangent = RPoint(values[2], values[3]);
    if (after != m_settings)
        emit changeRequested(after, tr("C² spline end tangents"));
}

void PlaneSplinePanel::showSettings(const PlaneSplineSettings& settings, const PlaneSplineScene& scene)
{
    m_showing = true;
    m_settings = settings;
    for (std::size_t i = 0; i < kPanelEnds.size(); ++i)
        if (kPanelEnds[i] == settings.ends)
            m_endsCombo->setCurrentIndex(static_cast<int>(i));
    for (std::size_t i = 0; i < kPanelParameters.size(); ++i)
        if (kPanelParameters[i] == settings.parameters)
            m_parametersCombo->setCurrentIndex(static_cast<int>(i));
    const std::array<Rational, 4> values{settings.startTangent.x, settings.startTangent.y, settings.endTangent.x,
                                         settings.endTangent.y};
    const bool clamped = settings.ends == ParametricEnds::Clamped;
    for (std::size_t i = 0; i < values.size(); ++i) {
        m_tangentEdits[i]->setText(rationalText(values[i]));
        m_tangentEdits[i]->setEnabled(clamped);
    }
    m_startLabel->setEnabled(clamped);
    m_endLabel->setEnabled(clamped);
    m_catmullRomCheck->setChecked(settings.catmullRomToo);
    m_error->setText(scene.spline.error);
    m_error->setVisible(!scene.spline.error.isEmpty());
    m_showing = false;
}

void PlaneSplinePanel::retranslate()
{
    m_endsLabel->setText(tr("End c&onditions:"));
    m_parametersLabel->setText(tr("Knot spacin&g:"));
    for (std::size_t i = 0; i < kPanelEnds.size(); ++i)
        m_endsCombo->setItemText(static_cast<int>(i), planeSplineEndsLabel(kPanelEnds[i]));
    for (std::size_t i = 0; i < kPanelParameters.size(); ++i)
        m_parametersCombo->setItemText(static_cast<int>(i), planeSplineParametersLabel(kPanelParameters[i]));
    m_endsCombo->setToolTip(tr("Def 2.1 leaves two conditions free; the ends fix them. Natural: p″ = 0 at both ends. "
                               "Clamped: the given end tangents. Not-a-knot: p‴ continuous at the second and last but one "
                               "points. Periodic: a closed curve, C² at every point."));
    m_parametersCombo->setToolTip(tr("How the parameter advances from point to point: by 1 (uniform), by the distance "
                                     "(chord length) or by its square root (centripetal)."));
    m_startLabel->setText(tr("&Initial tangent:"));
    m_endLabel->setText(tr("&Final tangent:"));
    const QString x = tr("x component"), y = tr("y component");
    for (std::size_t i = 0; i < m_tangentEdits.size(); ++i)
        m_tangentEdits[i]->setAccessibleName(
            (i < 2 ? tr("Initial tangent, %1") : tr("Final tangent, %1")).arg(i % 2 == 0 ? x : y));
    m_catmullRomCheck->setText(tr("Catmull-Rom τ = 1/2 of the same points"));
}

} // namespace granota::ui
