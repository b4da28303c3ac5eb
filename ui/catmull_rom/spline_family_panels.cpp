#include "ui/catmull_rom/spline_family_panels.h"

#include "ui/catmull_rom/function_data_panel.h"
#include "ui/catmull_rom/plane_spline_panel.h"
#include "ui/catmull_rom/spline_family_examples.h"

#include <QPushButton>
#include <QVBoxLayout>

namespace granota::ui {

SplineFamilyPanels::SplineFamilyPanels(QWidget* parent) : QGroupBox(parent)
{
    m_plane = new PlaneSplinePanel(this);
    m_data = new FunctionDataPanel(this);
    m_example = new QPushButton(this);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_plane);
    layout->addWidget(m_data);
    layout->addWidget(m_example);
    connect(m_plane, &PlaneSplinePanel::changeRequested, this, [this](const PlaneSplineSettings& plane, const QString& text) {
        CatmullRomSettings after = m_settings;
        after.planeSpline = plane;
        emit changeRequested(after, text);
    });
    connect(m_plane, &PlaneSplinePanel::refused, this, &SplineFamilyPanels::refused);
    connect(m_data, &FunctionDataPanel::changeRequested, this, [this](const FunctionDataSettings& data, const QString& text) {
        CatmullRomSettings after = m_settings;
        after.functionData = data;
        emit changeRequested(after, text);
    });
    connect(m_example, &QPushButton::clicked, this, [this] {
        CatmullRomSettings after = m_settings;
        if (m_settings.family == CurveFamily::PlaneSpline) {
            // §4.12's closed outline through the body's vertices, against the closed C² spline.
            after.planeSpline.ends = ParametricEnds::Periodic;
            after.planeSpline.catmullRomToo = true;
            emit exampleRequested(frogOutlineExamplePoints(), after, tr("Frog outline example"));
        } else {
            after.functionData = FunctionDataSettings{};
            emit exampleRequested(d3Shape38ExamplePoints(), after, tr("d3-shape #38 example"));
        }
    });
    retranslate();
}

void SplineFamilyPanels::showState(const CatmullRomSettings& settings, const CatmullRomScene& scene,
                                   const std::vector<Point>& points)
{
    m_settings = settings;
    const bool plane = settings.family == CurveFamily::PlaneSpline, data = settings.family == CurveFamily::FunctionData;
    setVisible(plane || data);
    m_plane->setVisible(plane);
    m_data->setVisible(data);
    if (plane)
        m_plane->showSettings(settings.planeSpline, scene.planeSpline);
    if (data)
        m_data->showSettings(settings.functionData, scene.functionData, points);
    retranslate();
}

void SplineFamilyPanels::retranslate()
{
    const bool plane = m_settings.family == CurveFamily::PlaneSpline;
    setTitle(plane ? tr("C² spline in the plane") : tr("Function data"));
    m_example->setText(plane ? tr("Example: t&he frog's outline points") : tr("Example: d3-s&hape #38 data"));
    m_example->setToolTip(plane ? tr("The frog body's vertices at rest, closed: the C² spline against the Catmull-Rom "
                                     "outline of §4.12.")
                                : tr("Data where the natural spline dips about 98 below its neighbouring values "
                                     "(d3-shape issue #38); the monotone schemes do not."));
    m_plane->retranslate();
    m_data->retranslate();
}

} // namespace granota::ui
