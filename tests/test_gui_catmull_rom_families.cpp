// The Catmull-Rom tab's family selector (issue 37; docs/spline-families.md "The family
// selector"): Catmull-Rom stays the default and old documents load as it, switching family is
// one undo step, and the document keeps the family.
#include "ui/catmull_rom/catmull_rom_tab.h"
#include "ui/catmull_rom/curve_family.h"
#include "ui/catmull_rom/family_panel.h"
#include "ui/common/point_editor.h"

#include <QComboBox>
#include <QJsonDocument>
#include <QTest>
#include <QUndoStack>
#include "tests/test_main.h"

using namespace granota;
using namespace granota::ui;

namespace {

/// Saved, written as text and read back, as a document would be.
QJsonObject throughText(const QJsonObject& state) { return QJsonDocument::fromJson(QJsonDocument(state).toJson()).object(); }

} // namespace

class TestGuiCatmullRomFamilies : public QObject {
    Q_OBJECT
private slots:
    void keysRoundTrip()
    {
        // The document keys of the brief, spelled out here (not read from curve_family.cpp).
        const QStringList keys{QStringLiteral("catmull-rom"), QStringLiteral("cardinal"),     QStringLiteral("kochanek-bartels"),
                               QStringLiteral("hermite"),     QStringLiteral("plane-spline"), QStringLiteral("function-data")};
        QCOMPARE(int(kCurveFamilies.size()), keys.size());
        for (std::size_t i = 0; i < kCurveFamilies.size(); ++i) {
            QCOMPARE(curveFamilyKey(kCurveFamilies[i]), keys[int(i)]);
            QCOMPARE(curveFamilyFromKey(keys[int(i)]), std::optional<CurveFamily>(kCurveFamilies[i]));
            QVERIFY(!curveFamilyName(kCurveFamilies[i]).isEmpty());
        }
        QVERIFY(!curveFamilyFromKey(QStringLiteral("bezier")));
    }

    void catmullRomIsTheDefault()
    {
        CatmullRomTab tab;
        QVERIFY(tab.settings().family == CurveFamily::CatmullRom);
        QCOMPARE(tab.saveState().value(QStringLiteral("family")).toString(), QStringLiteral("catmull-rom"));
        QVERIFY(tab.scene().family.bezier.empty()); // the τ curves are drawn, no family curve
        QCOMPARE(tab.familyPanel()->familyCombo()->currentIndex(), 0);
    }

    void oldDocumentLoadsAsCatmullRom()
    {
        CatmullRomTab tab;
        tab.setFamily(CurveFamily::KochanekBartels);
        QJsonObject old = tab.saveState();
        old.remove(QStringLiteral("family")); // a document from before the selector
        QString error;
        QVERIFY2(tab.loadState(old, &error), qPrintable(error));
        QVERIFY(tab.settings().family == CurveFamily::CatmullRom);
    }

    void unknownFamilyIsRefused()
    {
        CatmullRomTab tab;
        const QJsonObject before = tab.saveState();
        QJsonObject bad = before;
        bad.insert(QStringLiteral("family"), QStringLiteral("nurbs"));
        QString error;
        QVERIFY(!tab.loadState(bad, &error));
        QVERIFY(!error.isEmpty());
        QCOMPARE(tab.saveState(), before); // nothing the user made is lost
    }

    void switchingFamilyIsOneUndoStep()
    {
        CatmullRomTab tab;
        const int count = tab.undoStack()->count();
        // Through the combo box, as the user does.
        QComboBox* combo = tab.familyPanel()->familyCombo();
        combo->setCurrentIndex(int(CurveFamily::Hermite));
        QVERIFY(tab.settings().family == CurveFamily::Hermite);
        QCOMPARE(tab.undoStack()->count(), count + 1);
        tab.undoStack()->undo();
        QVERIFY(tab.settings().family == CurveFamily::CatmullRom);
        QCOMPARE(combo->currentIndex(), int(CurveFamily::CatmullRom));
        tab.undoStack()->redo();
        QVERIFY(tab.settings().family == CurveFamily::Hermite);
        QCOMPARE(combo->currentIndex(), int(CurveFamily::Hermite));
    }

    void familySavedAndRead()
    {
        for (CurveFamily f : kCurveFamilies) {
            CatmullRomTab tab;
            tab.setFamily(f);
            const QJsonObject saved = tab.saveState();
            QCOMPARE(saved.value(QStringLiteral("family")).toString(), curveFamilyKey(f));
            CatmullRomTab other;
            QString error;
            QVERIFY2(other.loadState(throughText(saved), &error), qPrintable(error));
            QVERIFY(other.settings() == tab.settings());
            QCOMPARE(other.saveState(), saved);
        }
    }
};

GRANOTA_TEST_MAIN(TestGuiCatmullRomFamilies)
#include "test_gui_catmull_rom_families.moc"
