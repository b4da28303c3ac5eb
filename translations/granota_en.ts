<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
    <context>
        <name>CatmullRomCurves</name>
        <message>
            <location filename="../ui/catmull_rom_curves.cpp" line="58" />
            <source>An open curve needs at least 2 points.</source>
            <translation>An open curve needs at least 2 points.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_curves.cpp" line="59" />
            <source>A single segment (Def 2.8) needs at least 4 points.</source>
            <translation>A single segment (Def 2.8) needs at least 4 points.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_curves.cpp" line="60" />
            <source>A cyclic or closed curve needs at least 3 points.</source>
            <translation>A cyclic or closed curve needs at least 3 points.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_curves.cpp" line="62" />
            <source>A point or a tension is not a finite number.</source>
            <translation>A point or a tension is not a finite number.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_curves.cpp" line="63" />
            <source>The curve overflows: the coordinates are too large.</source>
            <translation>The curve overflows: the coordinates are too large.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_curves.cpp" line="65" />
            <source>No cubic spline (Def 2.3): the points are not a function of x — their abscissae must increase strictly from q0 to qn.</source>
            <translation>No cubic spline (Def 2.3): the points are not a function of x — their abscissae must increase strictly from q0 to qn.</translation>
        </message>
        <message>
            <source>No unique cubic spline with these ends: as Ex 2.1, the last but one abscissa must not be 0.</source>
            <translation>No unique cubic spline with these ends: as Ex 2.1, the last but one abscissa must not be 0.</translation>
        </message>
    </context>
    <context>
        <name>CatmullRomReport</name>
        <message numerus="yes">
            <location filename="../ui/catmull_rom_report.cpp" line="62" />
            <source>… and %n more segments.</source>
            <translation>
                <numerusform>… and %n more segments.</numerusform>
                <numerusform>… and %n more segments.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="71" />
            <source>%1 jumps at x = %2: left %3, right %4 (jump %5)</source>
            <translation>%1 jumps at x = %2: left %3, right %4 (jump %5)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="75" />
            <source>%1 does not interpolate (%2, %3): %1(%2) = %4</source>
            <translation>%1 does not interpolate (%2, %3): %1(%2) = %4</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="79" />
            <source>The point (%1, %2) lies outside the domain.</source>
            <translation>The point (%1, %2) lies outside the domain.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="91" />
            <source>not continuous</source>
            <translation>not continuous</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="94" />
            <source>C^%1 at every knot</source>
            <translation>C^%1 at every knot</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="97" />
            <source>C^%1, not C^%2</source>
            <translation>C^%1, not C^%2</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/catmull_rom_report.cpp" line="101" />
            <source>interpolates all %n points</source>
            <translation>
                <numerusform>interpolates all %n point</numerusform>
                <numerusform>interpolates all %n points</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="103" />
            <source>does not interpolate every point</source>
            <translation>does not interpolate every point</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="117" />
            <location filename="../ui/catmull_rom_report.cpp" line="180" />
            <source>knot</source>
            <translation>knot</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="147" />
            <source>no interior knot</source>
            <translation>no interior knot</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/catmull_rom_report.cpp" line="150" />
            <source>equal tangents at all %n knots (C¹)</source>
            <translation>
                <numerusform>equal tangents at all %n knots (C¹)</numerusform>
                <numerusform>equal tangents at all %n knots (C¹)</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="153" />
            <source>C² too (p″ matches)</source>
            <translation>C² too (p″ matches)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="154" />
            <source>not C²: p″ jumps</source>
            <translation>not C²: p″ jumps</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/catmull_rom_report.cpp" line="158" />
            <source>parallel tangents at all %n knots (G¹), not equal ones (C¹) in the local parameters</source>
            <translation>
                <numerusform>parallel tangents at all %n knots (G¹), not equal ones (C¹) in the local parameters</numerusform>
                <numerusform>parallel tangents at all %n knots (G¹), not equal ones (C¹) in the local parameters</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="163" />
            <source>the tangents differ at some knots</source>
            <translation>the tangents differ at some knots</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="180" />
            <source>end of the segment before</source>
            <translation>end of the segment before</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="181" />
            <source>start of the segment after</source>
            <translation>start of the segment after</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="188" />
            <source>Matrix form (Lemma 2.3)</source>
            <translation>Matrix form (Lemma 2.3)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="207" />
            <source>Blending functions wⱼ(t, τ) (Def 2.9, Cor 2.1)</source>
            <translation>Blending functions wⱼ(t, τ) (Def 2.9, Cor 2.1)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="220" />
            <source>Processing's curveTightness</source>
            <translation>Processing's curveTightness</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="221" />
            <source>Processing draws the same curves with curveTightness(s), τ = (1 − s)/2: s = 0 (its default) is τ = 1/2.</source>
            <translation>Processing draws the same curves with curveTightness(s), τ = (1 − s)/2: s = 0 (its default) is τ = 1/2.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="255" />
            <source>Ex 2.1 as printed in the thesis</source>
            <translation>Ex 2.1 as printed in the thesis</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="261" />
            <source>The check of Def 2.3 on the printed pieces:</source>
            <translation>The check of Def 2.3 on the printed pieces:</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="267" />
            <source>%1 as printed misses both of its points by the same constant: it lacks %2.</source>
            <translation>%1 as printed misses both of its points by the same constant: it lacks %2.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="270" />
            <source>Correct %1:</source>
            <translation>Correct %1:</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="275" />
            <source>The corrected spline:</source>
            <translation>The corrected spline:</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="277" />
            <source>Ex 2.1's spline is a cubic spline (Def 2.3) but not the natural one: s″ ≠ 0 at its ends, so its pieces differ from those above.</source>
            <translation>Ex 2.1's spline is a cubic spline (Def 2.3) but not the natural one: s″ ≠ 0 at its ends, so its pieces differ from those above.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="286" />
            <source>Cubic spline C² (Def 2.3), natural ends</source>
            <translation>Cubic spline C² (Def 2.3), natural ends</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="309" />
            <source>In decimals, each piece in powers of u = x − xᵢ:</source>
            <translation>In decimals, each piece in powers of u = x − xᵢ:</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="326" />
            <source>open</source>
            <translation>open</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="327" />
            <source>cyclic</source>
            <translation>cyclic</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="328" />
            <source>closed</source>
            <translation>closed</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="329" />
            <source>single segment</source>
            <translation>single segment</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="351" />
            <source>Segments, t ∈ [0, 1]: %1</source>
            <translation>Segments, t ∈ [0, 1]: %1</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="353" />
            <source>Centripetal and chordal spacing: coefficients in decimals.</source>
            <translation>Centripetal and chordal spacing: coefficients in decimals.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="354" />
            <source>The points are not small fractions: coefficients in decimals.</source>
            <translation>The points are not small fractions: coefficients in decimals.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="370" />
            <source>Tangents at the knots (Prop 2.3)</source>
            <translation>Tangents at the knots (Prop 2.3)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="371" />
            <source>Catmull-Rom curves are C¹: at every knot cᵢ′(1) = cᵢ₊₁′(0) = τ(qᵢ₊₁ − qᵢ₋₁).</source>
            <translation>Catmull-Rom curves are C¹: at every knot cᵢ′(1) = cᵢ₊₁′(0) = τ(qᵢ₊₁ − qᵢ₋₁).</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="394" />
            <source>Smoothness compared (§2.3)</source>
            <translation>Smoothness compared (§2.3)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="397" />
            <source>Bézier, degree %1</source>
            <translation>Bézier, degree %1</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="397" />
            <source>C^∞: one polynomial</source>
            <translation>C^∞: one polynomial</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="398" />
            <source>only q0 and q%1</source>
            <translation>only q0 and q%1</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="400" />
            <source>Catmull-Rom, τ = %1</source>
            <translation>Catmull-Rom, τ = %1</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="401" />
            <source>C^%1 at the joins (checked)</source>
            <translation>C^%1 at the joins (checked)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="402" />
            <source>not C¹ at the joins (checked)</source>
            <translation>not C¹ at the joins (checked)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="403" />
            <location filename="../ui/catmull_rom_report.cpp" line="407" />
            <source>every point</source>
            <translation>every point</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="405" />
            <source>Cubic spline</source>
            <translation>Cubic spline</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="406" />
            <source>C² (checked above)</source>
            <translation>C² (checked above)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="406" />
            <source>not defined</source>
            <translation>not defined</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="408" />
            <source>curve</source>
            <translation>curve</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="408" />
            <source>smoothness</source>
            <translation>smoothness</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="408" />
            <source>passes through</source>
            <translation>passes through</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="410" />
            <source>The Bézier curve only approaches the inner points: Catmull-Rom passes through all of them, which is why the thesis chose it for the frog (§2.3, §4.12).</source>
            <translation>The Bézier curve only approaches the inner points: Catmull-Rom passes through all of them, which is why the thesis chose it for the frog (§2.3, §4.12).</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>broken</source>
            <translation>broken</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>At every knot at least C^%1 and G^%2 (of %n knots).</source>
            <translation>
                <numerusform>At every knot at least C^%1 and G^%2 (of %n knots).</numerusform>
                <numerusform>At every knot at least C^%1 and G^%2 (of %n knots).</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>undefined: p′ = 0</source>
            <translation>undefined: p′ = 0</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>the tangent turns by %1°</source>
            <translation>the tangent turns by %1°</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>C order</source>
            <translation>C order</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>G order</source>
            <translation>G order</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>jump</source>
            <translation>jump</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>curvature κ left → right</source>
            <translation>curvature κ left → right</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>… and %n more knots.</source>
            <translation>
                <numerusform>… and %n more knots.</numerusform>
                <numerusform>… and %n more knots.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>Bézier segments and the knots (§2.3)</source>
            <translation>Bézier segments and the knots (§2.3)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>Each segment as a cubic Bézier curve: b0 = p(0), b1 = b0 + p′(0)/3, b2 = b3 − p′(1)/3, b3 = p(1); for Def 2.8, b1 = p1 + τ(p2 − p0)/3 and b2 = p2 − τ(p3 − p1)/3. Cᵏ: equal derivatives up to order k at the knot; Gᵏ: the same tangent direction (G¹) and curvature (G²).</source>
            <translation>Each segment as a cubic Bézier curve: b0 = p(0), b1 = b0 + p′(0)/3, b2 = b3 − p′(1)/3, b3 = p(1); for Def 2.8, b1 = p1 + τ(p2 − p0)/3 and b2 = p2 − τ(p3 − p1)/3. Cᵏ: equal derivatives up to order k at the knot; Gᵏ: the same tangent direction (G¹) and curvature (G²).</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>Centripetal and chordal spacing: the derivatives are taken in the knot parameter u, in which segment i has length hᵢ = |qᵢ₊₁ − qᵢ|ᵅ. There the curve is C¹; in the local parameters the tangents are only parallel (G¹).</source>
            <translation>Centripetal and chordal spacing: the derivatives are taken in the knot parameter u, in which segment i has length hᵢ = |qᵢ₊₁ − qᵢ|ᵅ. There the curve is C¹; in the local parameters the tangents are only parallel (G¹).</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>Cubic spline C² (Def 2.3)</source>
            <translation>Cubic spline C² (Def 2.3)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>Its graph (x, s(x)) piece by piece, x = xᵢ + hᵢ u, u ∈ [0, 1]; the derivatives in x.</source>
            <translation>Its graph (x, s(x)) piece by piece, x = xᵢ + hᵢ u, u ∈ [0, 1]; the derivatives in x.</translation>
        </message>
        <message>
            <source>Cubic spline C² (Def 2.3), %1</source>
            <translation>Cubic spline C² (Def 2.3), %1</translation>
        </message>
        <message>
            <source>natural ends</source>
            <translation>natural ends</translation>
        </message>
        <message>
            <source>clamped ends</source>
            <translation>clamped ends</translation>
        </message>
        <message>
            <source>not-a-knot ends</source>
            <translation>not-a-knot ends</translation>
        </message>
        <message>
            <source>the ends of Ex 2.1</source>
            <translation>the ends of Ex 2.1</translation>
        </message>
        <message>
            <source>With Ex 2.1&apos;s ends — s₁‴ = 0 (s₁ is a parabola) and no x² term in s₃ — the pieces above are exactly the corrected ones (docs/thesis-errata.md).</source>
            <translation>With Ex 2.1&apos;s ends — s₁‴ = 0 (s₁ is a parabola) and no x² term in s₃ — the pieces above are exactly the corrected ones (docs/thesis-errata.md).</translation>
        </message>
        <message>
            <source>Ex 2.1&apos;s spline is a cubic spline (Def 2.3) but not the natural one: s″ ≠ 0 at its ends, so its pieces differ from those above. Choose the ends “As Ex 2.1” to get them.</source>
            <translation>Ex 2.1&apos;s spline is a cubic spline (Def 2.3) but not the natural one: s″ ≠ 0 at its ends, so its pieces differ from those above. Choose the ends “As Ex 2.1” to get them.</translation>
        </message>
        <message>
            <source>With Ex 2.1&apos;s ends — s₁‴ = 0 (s₁ is a parabola) and no x² term in s₃ — the pieces above are exactly the corrected ones (docs/thesis-errata.md, “Ex 2.1”).</source>
            <translation>With Ex 2.1&apos;s ends — s₁‴ = 0 (s₁ is a parabola) and no x² term in s₃ — the pieces above are exactly the corrected ones (docs/thesis-errata.md, “Ex 2.1”).</translation>
        </message>
        <message>
            <source>Ex 2.1&apos;s spline is a cubic spline (Def 2.3) but not the natural one: s″ ≠ 0 at its ends, so its pieces differ from those above. Choose the ends “As Ex 2.1” to get them (docs/thesis-errata.md, “Ex 2.1”).</source>
            <translation>Ex 2.1&apos;s spline is a cubic spline (Def 2.3) but not the natural one: s″ ≠ 0 at its ends, so its pieces differ from those above. Choose the ends “As Ex 2.1” to get them (docs/thesis-errata.md, “Ex 2.1”).</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::BernsteinTab</name>
        <message>
            <source>Ex %1: the curve written in the Bernstein basis is in the panel on the right. Its control points are now the De Casteljau tab's too (Ctrl+Z on either tab gives the old ones back).</source>
            <translation>Ex %1: the curve written in the Bernstein basis is in the panel on the right. Its control points are now the De Casteljau tab's too (Ctrl+Z on either tab gives the old ones back).</translation>
        </message>
        <message>
            <source>Degree n = %1</source>
            <translation>Degree n = %1</translation>
        </message>
        <message>
            <source>Move t</source>
            <translation>Move t</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="326" />
            <source>At t = %1 the weights sum to %2.&lt;br&gt;Def 2.6: %3 = %4&lt;br&gt;De Casteljau: %5 = %6 (difference %7)</source>
            <translation>At t = %1 the weights sum to %2.&lt;br&gt;Def 2.6: %3 = %4&lt;br&gt;De Casteljau: %5 = %6 (difference %7)</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/bernstein_tab.cpp" line="332" />
            <source>Weights of the %n control points of the De Casteljau tab at t (Def 2.6)</source>
            <translation>
                <numerusform>Weights of the %n control points of the De Casteljau tab at t (Def 2.6)</numerusform>
                <numerusform>Weights of the %n control points of the De Casteljau tab at t (Def 2.6)</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="393" />
            <source>yes</source>
            <translation>yes</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="395" />
            <source>%1 %2 %3 — residual at t: %4; exact as polynomials: %5</source>
            <translation>%1 %2 %3 — residual at t: %4; exact as polynomials: %5</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="397" />
            <source>no</source>
            <translation>no</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="399" />
            <source>Partition of unity:</source>
            <translation>Partition of unity:</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="402" />
            <source>Symmetry:</source>
            <translation>Symmetry:</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="407" />
            <source>Recursion (Lemma 2.1):</source>
            <translation>Recursion (Lemma 2.1):</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="414" />
            <source>Recursion (Lemma 2.1): needs n ≥ 1.</source>
            <translation>Recursion (Lemma 2.1): needs n ≥ 1.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="429" />
            <source>Bernstein polynomials of degree %1 (Def 2.5)</source>
            <translation>Bernstein polynomials of degree %1 (Def 2.5)</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="440" />
            <source>The De Casteljau tab's curve in the Bernstein basis (Def 2.6)</source>
            <translation>The De Casteljau tab's curve in the Bernstein basis (Def 2.6)</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="443" />
            <source>The control points are not small fractions, so the curve is not expanded exactly.</source>
            <translation>The control points are not small fractions, so the curve is not expanded exactly.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="445" />
            <source>The expansion is shown up to degree %1; the curve has degree %2.</source>
            <translation>The expansion is shown up to degree %1; the curve has degree %2.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="468" />
            <source>Degree n:</source>
            <translation>Degree n:</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="469" />
            <source>The degree n of the Bernstein polynomials Bᵢⁿ(t) = C(n,i) tⁱ (1−t)ⁿ⁻ⁱ (Def 2.5).</source>
            <translation>The degree n of the Bernstein polynomials Bᵢⁿ(t) = C(n,i) tⁱ (1−t)ⁿ⁻ⁱ (Def 2.5).</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="472" />
            <source>All degrees up to n</source>
            <translation>All degrees up to n</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="473" />
            <source>Overlay the polynomials of every degree 0…n, one colour per degree, like the tots option of the thesis's Matlab Rep_Pol_Bernstein (Ex 2.4, Figure 2.4).</source>
            <translation>Overlay the polynomials of every degree 0…n, one colour per degree, like the tots option of the thesis's Matlab Rep_Pol_Bernstein (Ex 2.4, Figure 2.4).</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="475" />
            <source>value</source>
            <translation>value</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="476" />
            <source>The Bernstein polynomials on [0, 1] (Def 2.5). Move the mouse to read their values; click or drag to move t, shared with the De Casteljau tab.</source>
            <translation>The Bernstein polynomials on [0, 1] (Def 2.5). Move the mouse to read their values; click or drag to move t, shared with the De Casteljau tab.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="478" />
            <source>Def 2.6: c(t) = Σ Bᵢⁿ(t) Pᵢ. Each bar is the weight of one control point of the De Casteljau tab at the current t; they sum to 1 (partition of unity).</source>
            <translation>Def 2.6: c(t) = Σ Bᵢⁿ(t) Pᵢ. Each bar is the weight of one control point of the De Casteljau tab at the current t; they sum to 1 (partition of unity).</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="480" />
            <source>weight</source>
            <translation>weight</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="481" />
            <source>The point c(t) from the Bernstein sum (Def 2.6) and from De Casteljau's algorithm (Def 2.4): equal by Prop 2.1.</source>
            <translation>The point c(t) from the Bernstein sum (Def 2.6) and from De Casteljau's algorithm (Def 2.4): equal by Prop 2.1.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="483" />
            <source>Properties at the current n and t</source>
            <translation>Properties at the current n and t</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="484" />
            <source>Each property is checked twice: in floating point at t (the residual) and exactly, as polynomials with rational coefficients.</source>
            <translation>Each property is checked twice: in floating point at t (the residual) and exactly, as polynomials with rational coefficients.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="486" />
            <source>Partition of unity: the Bernstein polynomials of one degree sum to 1.</source>
            <translation>Partition of unity: the Bernstein polynomials of one degree sum to 1.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="487" />
            <source>Symmetry: Bᵢⁿ(t) = Bₙ₋ᵢⁿ(1 − t).</source>
            <translation>Symmetry: Bᵢⁿ(t) = Bₙ₋ᵢⁿ(1 − t).</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="488" />
            <source>Lemma 2.1: Bᵢⁿ = (1 − t) Bᵢⁿ⁻¹ + t Bᵢ₋₁ⁿ⁻¹.</source>
            <translation>Lemma 2.1: Bᵢⁿ = (1 − t) Bᵢⁿ⁻¹ + t Bᵢ₋₁ⁿ⁻¹.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="489" />
            <source>The Bernstein polynomials expanded in powers of t (Ex 2.4) and the De Casteljau tab's curve written in the Bernstein basis (Ex 2.5, Ex 2.6).</source>
            <translation>The Bernstein polynomials expanded in powers of t (Ex 2.4) and the De Casteljau tab's curve written in the Bernstein basis (Ex 2.5, Ex 2.6).</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="517" />
            <source>The Bernstein degree must be a whole number from 0 to %1.</source>
            <translation>The Bernstein degree must be a whole number from 0 to %1.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="523" />
            <source>The Bernstein mode must be "single" or "all".</source>
            <translation>The Bernstein mode must be "single" or "all".</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="529" />
            <source>The parameter t must be a number between 0 and 1.</source>
            <translation>The parameter t must be a number between 0 and 1.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="546" />
            <source>Ex %1: the Bernstein polynomials of every degree up to %2.</source>
            <translation>Ex %1: the Bernstein polynomials of every degree up to %2.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="552" />
            <source>Load Ex %1</source>
            <translation>Load Ex %1</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="557" />
            <source>Ex %1: the curve written in the Bernstein basis is in the panel on the right.</source>
            <translation>Ex %1: the curve written in the Bernstein basis is in the panel on the right.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="613" />
            <source>Move the mouse over the plot to read Bᵢⁿ(t); click or drag to move t.</source>
            <translation>Move the mouse over the plot to read Bᵢⁿ(t); click or drag to move t.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.h" line="46" />
            <source>Bernstein</source>
            <translation>Bernstein</translation>
        </message>
        <message>
            <source>Mark t</source>
            <translation>Mark t</translation>
        </message>
        <message>
            <source>Hide the mark at t</source>
            <translation>Hide the mark at t</translation>
        </message>
        <message>
            <source>The dashed vertical line at the current t, shared with the De Casteljau tab. Off, the plot and its exports show the polynomials alone, as Figure 2.4 does.</source>
            <translation>The dashed vertical line at the current t, shared with the De Casteljau tab. Off, the plot and its exports show the polynomials alone, as Figure 2.4 does.</translation>
        </message>
        <message>
            <source>The Bernstein tab&apos;s “t_marker” must be true or false.</source>
            <translation>The Bernstein tab&apos;s “t_marker” must be true or false.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::CatmullRomTab</name>
        <message>
            <source>Exact results and points</source>
            <translation>Exact results and points</translation>
        </message>
        <message>
            <source>Tensions τ</source>
            <translation>Tensions τ</translation>
        </message>
        <message>
            <source>none</source>
            <translation>none</translation>
        </message>
        <message numerus="yes">
            <source>Catmull-Rom curves through %n point(s), tensions τ = %1.</source>
            <translation>
                <numerusform>Catmull-Rom curves through %n point, tensions τ = %1.</numerusform>
                <numerusform>Catmull-Rom curves through %n points, tensions τ = %1.</numerusform>
            </translation>
        </message>
        <message>
            <source>Catmull-Rom canvas</source>
            <translation>Catmull-Rom canvas</translation>
        </message>
        <message>
            <source>Drag a point; double-click to add one; pick a τ in the list and move its slider, or type one and press Enter.</source>
            <translation>Drag a point; double-click to add one; pick a τ in the list and move its slider, or type one and press Enter.</translation>
        </message>
        <message>
            <source>Select τ = %1</source>
            <translation>Select τ = %1</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="286" />
            <source>Tensions τ (Def 2.8)</source>
            <translation>Tensions τ (Def 2.8)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="287" />
            <source>The tension τ scales the tangents p′(0) = τ(p2 − p0), p′(1) = τ(p3 − p1) of every segment (Def 2.8): 0 gives straight segments, 1/2 is the usual value, negative values turn the tangents round (Ex 2.12). One curve per τ, in its colour.</source>
            <translation>The tension τ scales the tangents p′(0) = τ(p2 − p0), p′(1) = τ(p3 − p1) of every segment (Def 2.8): 0 gives straight segments, 1/2 is the usual value, negative values turn the tangents round (Ex 2.12). One curve per τ, in its colour.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="290" />
            <source>The tensions drawn, each with its colour and Processing's curveTightness(s), τ = (1 − s)/2. Select one for the slider, the blending plot and the tangent table.</source>
            <translation>The tensions drawn, each with its colour and Processing's curveTightness(s), τ = (1 − s)/2. Select one for the slider, the blending plot and the tangent table.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="292" />
            <source>τ, e.g. 1/2 or -0.5</source>
            <translation>τ, e.g. 1/2 or -0.5</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="293" />
            <source>Type a tension as a decimal or a fraction (-1/2), between −10 and 10, and press Enter.</source>
            <translation>Type a tension as a decimal or a fraction (-1/2), between −10 and 10, and press Enter.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="294" />
            <source>&amp;Add</source>
            <translation>&amp;Add</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="295" />
            <source>Add the typed tension: one more curve on the canvas (Ex 2.11 compares 0, 1/2 and 2).</source>
            <translation>Add the typed tension: one more curve on the canvas (Ex 2.11 compares 0, 1/2 and 2).</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="296" />
            <source>&amp;Remove</source>
            <translation>&amp;Remove</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="297" />
            <source>Remove the selected tension and its curve.</source>
            <translation>Remove the selected tension and its curve.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="298" />
            <source>Drag to change the selected tension in steps of 0.05, from −10 to 10; the curve, the blending functions and the exact panel follow.</source>
            <translation>Drag to change the selected tension in steps of 0.05, from −10 to 10; the curve, the blending functions and the exact panel follow.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="300" />
            <source>Curve (Def 2.10)</source>
            <translation>Curve (Def 2.10)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="301" />
            <source>&amp;Ends:</source>
            <translation>&amp;Ends:</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="302" />
            <source>open (ends repeated)</source>
            <translation>open (ends repeated)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="303" />
            <source>cyclic (n segments)</source>
            <translation>cyclic (n segments)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="304" />
            <source>closed (n + 1 segments)</source>
            <translation>closed (n + 1 segments)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="305" />
            <source>single segment (Def 2.8)</source>
            <translation>single segment (Def 2.8)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="306" />
            <source>How the end segments get their missing neighbours (Def 2.10, Matlab Rep_CatmullRom): open repeats q0 and qn (p1′(0) = τ(q1 − q0)); cyclic takes q₋₁ = qn and qn₊₁ = q0 (n segments, Ex 2.13); closed adds the segment from qn back to q0; a single segment (Def 2.8, Ex 2.11) keeps only the segments with both neighbours.</source>
            <translation>How the end segments get their missing neighbours (Def 2.10, Matlab Rep_CatmullRom): open repeats q0 and qn (p1′(0) = τ(q1 − q0)); cyclic takes q₋₁ = qn and qn₊₁ = q0 (n segments, Ex 2.13); closed adds the segment from qn back to q0; a single segment (Def 2.8, Ex 2.11) keeps only the segments with both neighbours.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="310" />
            <source>&amp;Parametrization:</source>
            <translation>&amp;Parametrization:</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="311" />
            <source>uniform (thesis)</source>
            <translation>uniform (thesis)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="312" />
            <source>centripetal (α = 1/2)</source>
            <translation>centripetal (α = 1/2)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="313" />
            <source>chordal (α = 1)</source>
            <translation>chordal (α = 1)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="314" />
            <source>Knot spacing |qᵢ₊₁ − qᵢ|ᵅ. The thesis uses uniform spacing (α = 0). Beyond it: centripetal (α = 1/2) avoids cusps and loops, chordal (α = 1) follows the chord lengths; the segments then join with parallel tangents (G¹).</source>
            <translation>Knot spacing |qᵢ₊₁ − qᵢ|ᵅ. The thesis uses uniform spacing (α = 0). Beyond it: centripetal (α = 1/2) avoids cusps and loops, chordal (α = 1) follows the chord lengths; the segments then join with parallel tangents (G¹).</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="317" />
            <source>Compare with &amp;Bézier</source>
            <translation>Compare with &amp;Bézier</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="318" />
            <source>Draw the Bézier curve that has the same points as control polygon (De Casteljau, Def 2.4): it passes only through q0 and qn, while Catmull-Rom passes through every point (§2.3).</source>
            <translation>Draw the Bézier curve that has the same points as control polygon (De Casteljau, Def 2.4): it passes only through q0 and qn, while Catmull-Rom passes through every point (§2.3).</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="321" />
            <source>Cubic &amp;spline (C²)</source>
            <translation>Cubic &amp;spline (C²)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="322" />
            <source>Draw the C² cubic spline of Def 2.3 through the same points, with the ends chosen below (a function of x: the abscissae must increase), and check its continuity at the knots: Bézier C^∞, Catmull-Rom C¹, cubic spline C² (§2.3, Ex 2.1).</source>
            <translation>Draw the C² cubic spline of Def 2.3 through the same points, with the ends chosen below (a function of x: the abscissae must increase), and check its continuity at the knots: Bézier C^∞, Catmull-Rom C¹, cubic spline C² (§2.3, Ex 2.1).</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="325" />
            <source>Compare open and &amp;cyclic ends</source>
            <translation>Compare open and &amp;cyclic ends</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="326" />
            <source>Also draw (dashed) and list the curve with the other end mode, as Ex 2.13 compares the cyclic and the open curve through the same points.</source>
            <translation>Also draw (dashed) and list the curve with the other end mode, as Ex 2.13 compares the cyclic and the open curve through the same points.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="328" />
            <source>Blending functions wⱼ(t, τ) (Def 2.9, Cor 2.1)</source>
            <translation>Blending functions wⱼ(t, τ) (Def 2.9, Cor 2.1)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="329" />
            <source>p(t) = Σ wⱼ(t, τ) pⱼ: the weight of each of the four points along a segment. They always add up to 1.</source>
            <translation>p(t) = Σ wⱼ(t, τ) pⱼ: the weight of each of the four points along a segment. They always add up to 1.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="331" />
            <source>Every &amp;τ</source>
            <translation>Every &amp;τ</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="332" />
            <source>Plot the blending functions of every tension in the list (one line style per τ), as Ex 2.12 does for τ = −2, 0, 1/2 and 2.</source>
            <translation>Plot the blending functions of every tension in the list (one line style per τ), as Ex 2.12 does for τ = −2, 0, 1/2 and 2.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="334" />
            <source>The blending functions w₀…w₃ of Cor 2.1 on t ∈ [0, 1].</source>
            <translation>The blending functions w₀…w₃ of Cor 2.1 on t ∈ [0, 1].</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="335" />
            <source>Exact results: segment polynomials (Lemma 2.3, Def 2.10), tangents at the knots (Prop 2.3), blending functions (Cor 2.1), and the comparisons of §2.3.</source>
            <translation>Exact results: segment polynomials (Lemma 2.3, Def 2.10), tangents at the knots (Prop 2.3), blending functions (Cor 2.1), and the comparisons of §2.3.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="337" />
            <source>Drag a point to move it; double-click to add one; Delete removes the selected point; drag the paper to pan, wheel to zoom.</source>
            <translation>Drag a point to move it; double-click to add one; Delete removes the selected point; drag the paper to pan, wheel to zoom.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="339" />
            <source>Exact results</source>
            <translation>Exact results</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="340" />
            <source>Points</source>
            <translation>Points</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="342" />
            <source>The points q0…qn as numbers; fractions such as 1/3 are accepted.</source>
            <translation>The points q0…qn as numbers; fractions such as 1/3 are accepted.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="350" />
            <source>τ = %1   (curveTightness %2)</source>
            <translation>τ = %1   (curveTightness %2)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="376" />
            <source>Selected: τ = %1, Processing's curveTightness(%2)</source>
            <translation>Selected: τ = %1, Processing's curveTightness(%2)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="420" />
            <source>τ = %1 is outside [−10, 10]: beyond that the curve is all overshoot. Not added.</source>
            <translation>τ = %1 is outside [−10, 10]: beyond that the curve is all overshoot. Not added.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="423" />
            <source>“%1” is not a tension: type a decimal (0.5) or a fraction (-1/2). Not added.</source>
            <translation>“%1” is not a tension: type a decimal (0.5) or a fraction (-1/2). Not added.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="427" />
            <location filename="../ui/catmull_rom_tab.cpp" line="476" />
            <source>τ = %1 is already in the list.</source>
            <translation>τ = %1 is already in the list.</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/catmull_rom_tab.cpp" line="431" />
            <source>At most %n tensions at a time: remove one first.</source>
            <translation>
                <numerusform>At most %n tensions at a time: remove one first.</numerusform>
                <numerusform>At most %n tensions at a time: remove one first.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="437" />
            <source>Add τ = %1</source>
            <translation>Add τ = %1</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="438" />
            <source>Added τ = %1.</source>
            <translation>Added τ = %1.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="447" />
            <source>At least one tension is needed.</source>
            <translation>At least one tension is needed.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="454" />
            <source>Remove τ = %1</source>
            <translation>Remove τ = %1</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="482" />
            <source>Change τ</source>
            <translation>Change τ</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="489" />
            <source>Change the ends</source>
            <translation>Change the ends</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="491" />
            <source>A single segment uses four points p0…p3 and joins p1 to p2; with more points, every segment that has both neighbours is drawn.</source>
            <translation>A single segment uses four points p0…p3 and joins p1 to p2; with more points, every segment that has both neighbours is drawn.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="499" />
            <source>Change the parametrization</source>
            <translation>Change the parametrization</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="506" />
            <source>Show the Bézier curve</source>
            <translation>Show the Bézier curve</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="506" />
            <source>Hide the Bézier curve</source>
            <translation>Hide the Bézier curve</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="513" />
            <source>Show the cubic spline</source>
            <translation>Show the cubic spline</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="513" />
            <source>Hide the cubic spline</source>
            <translation>Hide the cubic spline</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="520" />
            <source>Compare the ends</source>
            <translation>Compare the ends</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="527" />
            <source>Blending functions of every τ</source>
            <translation>Blending functions of every τ</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="689" />
            <source>dashed: %1 ends</source>
            <translation>dashed: %1 ends</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="691" />
            <source>Bézier curve of the same points</source>
            <translation>Bézier curve of the same points</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="694" />
            <source>no cubic spline: x must increase</source>
            <translation>no cubic spline: x must increase</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="694" />
            <source>cubic spline C²</source>
            <translation>cubic spline C²</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="796" />
            <location filename="../ui/catmull_rom_tab.cpp" line="798" />
            <location filename="../ui/catmull_rom_tab.cpp" line="799" />
            <source>Load Ex %1</source>
            <translation>Load Ex %1</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="826" />
            <source>The Catmull-Rom points are missing or not a list.</source>
            <translation>The Catmull-Rom points are missing or not a list.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="829" />
            <source>A Catmull-Rom curve needs between 2 and %1 points; the file has %2.</source>
            <translation>A Catmull-Rom curve needs between 2 and %1 points; the file has %2.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="836" />
            <source>Point %1 of the Catmull-Rom tab is not a pair of numbers.</source>
            <translation>Point %1 of the Catmull-Rom tab is not a pair of numbers.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="839" />
            <source>Point %1 of the Catmull-Rom tab is not a finite number.</source>
            <translation>Point %1 of the Catmull-Rom tab is not a finite number.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="845" />
            <source>The Catmull-Rom settings are not valid (“%1”): tensions must be numbers in [−10, 10], at most %2 of them, without repeats.</source>
            <translation>The Catmull-Rom settings are not valid (“%1”): tensions must be numbers in [−10, 10], at most %2 of them, without repeats.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.h" line="42" />
            <source>Catmull-Rom</source>
            <translation>Catmull-Rom</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="1" />
            <source>C&amp;urvature κ(s) in the plot</source>
            <translation>C&amp;urvature κ(s) in the plot</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="1" />
            <source>Plot the signed curvature κ of every curve on the canvas against its arc length s instead of the blending functions: κ jumps at the knots of a Catmull-Rom curve (C¹, not C²) and is continuous along the C² cubic spline (§2.3).</source>
            <translation>Plot the signed curvature κ of every curve on the canvas against its arc length s instead of the blending functions: κ jumps at the knots of a Catmull-Rom curve (C¹, not C²) and is continuous along the C² cubic spline (§2.3).</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="1" />
            <source>Curvature κ against arc length s (§2.3)</source>
            <translation>Curvature κ against arc length s (§2.3)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="1" />
            <source>κ = (x′y″ − y′x″)/|p′|³, positive where the curve turns left. A Catmull-Rom curve is C¹ but not C²: p″ jumps at its knots and so does κ (a break in the line). The C² cubic spline's κ is continuous, and the Bézier curve is one polynomial (C^∞).</source>
            <translation>κ = (x′y″ − y′x″)/|p′|³, positive where the curve turns left. A Catmull-Rom curve is C¹ but not C²: p″ jumps at its knots and so does κ (a break in the line). The C² cubic spline's κ is continuous, and the Bézier curve is one polynomial (C^∞).</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="1" />
            <source>κ(s) of every curve drawn, in its colour and line style as on the canvas; the light vertical lines are the knots of the selected τ.</source>
            <translation>κ(s) of every curve drawn, in its colour and line style as on the canvas; the light vertical lines are the knots of the selected τ.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="1" />
            <source>Plot the curvature</source>
            <translation>Plot the curvature</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="1" />
            <source>Plot the blending functions</source>
            <translation>Plot the blending functions</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="1" />
            <source>arc length s</source>
            <translation>arc length s</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="1" />
            <source>curvature κ</source>
            <translation>curvature κ</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="1" />
            <source>τ = %1, %2 ends</source>
            <translation>τ = %1, %2 ends</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="1" />
            <source>Bézier</source>
            <translation>Bézier</translation>
        </message>
        <message>
            <source>An end slope is a number between −10 and 10, such as 1/2 or -0.25.</source>
            <translation>An end slope is a number between −10 and 10, such as 1/2 or -0.25.</translation>
        </message>
        <message>
            <source>Cat&amp;mull-Rom curves</source>
            <translation>Cat&amp;mull-Rom curves</translation>
        </message>
        <message>
            <source>Draw the Catmull-Rom curve of each tension. Hide them to see the cubic spline alone, as Fig 2.1 shows Ex 2.1&apos;s.</source>
            <translation>Draw the Catmull-Rom curve of each tension. Hide them to see the cubic spline alone, as Fig 2.1 shows Ex 2.1&apos;s.</translation>
        </message>
        <message>
            <source>Spline e&amp;nds:</source>
            <translation>Spline e&amp;nds:</translation>
        </message>
        <message>
            <source>Natural (s″ = 0)</source>
            <translation>Natural (s″ = 0)</translation>
        </message>
        <message>
            <source>Clamped (slopes)</source>
            <translation>Clamped (slopes)</translation>
        </message>
        <message>
            <source>Not-a-knot</source>
            <translation>Not-a-knot</translation>
        </message>
        <message>
            <source>As Ex 2.1</source>
            <translation>As Ex 2.1</translation>
        </message>
        <message>
            <source>Def 2.3 leaves two degrees of freedom; the ends fix them. Natural: s″ = 0 at both ends. Clamped: the end slopes are given. Not-a-knot: the first two pieces are one cubic, and so are the last two. As Ex 2.1: the first piece is a parabola (s₁‴ = 0) and the last has no x² term — the ends that give Ex 2.1&apos;s pieces.</source>
            <translation>Def 2.3 leaves two degrees of freedom; the ends fix them. Natural: s″ = 0 at both ends. Clamped: the end slopes are given. Not-a-knot: the first two pieces are one cubic, and so are the last two. As Ex 2.1: the first piece is a parabola (s₁‴ = 0) and the last has no x² term — the ends that give Ex 2.1&apos;s pieces.</translation>
        </message>
        <message>
            <source>End s&amp;lopes:</source>
            <translation>End s&amp;lopes:</translation>
        </message>
        <message>
            <source>s′(x₀), the slope at the first point (clamped ends)</source>
            <translation>s′(x₀), the slope at the first point (clamped ends)</translation>
        </message>
        <message>
            <source>s′(xₖ), the slope at the last point (clamped ends)</source>
            <translation>s′(xₖ), the slope at the last point (clamped ends)</translation>
        </message>
        <message>
            <source>Change the spline&apos;s ends</source>
            <translation>Change the spline&apos;s ends</translation>
        </message>
        <message>
            <source>Change the spline&apos;s end slopes</source>
            <translation>Change the spline&apos;s end slopes</translation>
        </message>
        <message>
            <source>Show the Catmull-Rom curves</source>
            <translation>Show the Catmull-Rom curves</translation>
        </message>
        <message>
            <source>Hide the Catmull-Rom curves</source>
            <translation>Hide the Catmull-Rom curves</translation>
        </message>
        <message>
            <source>Poin&amp;ts</source>
            <translation>Poin&amp;ts</translation>
        </message>
        <message>
            <source>Draw the points qᵢ that the curves interpolate, their labels and their polygon; off, the curves alone, like puntvis = false in the thesis&apos;s Matlab Rep_CatmullRom. The table still edits the points.</source>
            <translation>Draw the points qᵢ that the curves interpolate, their labels and their polygon; off, the curves alone, like puntvis = false in the thesis&apos;s Matlab Rep_CatmullRom. The table still edits the points.</translation>
        </message>
        <message>
            <source>Show the points</source>
            <translation>Show the points</translation>
        </message>
        <message>
            <source>Hide the points</source>
            <translation>Hide the points</translation>
        </message>
        <message>
            <source>Back to the Catmull-Rom tangents</source>
            <translation>Back to the Catmull-Rom tangents</translation>
        </message>
        <message>
            <source>Change B</source>
            <translation>Change B</translation>
        </message>
        <message>
            <source>Change C</source>
            <translation>Change C</translation>
        </message>
        <message>
            <source>Change T</source>
            <translation>Change T</translation>
        </message>
        <message>
            <source>Change the cardinal tension</source>
            <translation>Change the cardinal tension</translation>
        </message>
        <message>
            <source>Conventions</source>
            <translation>Conventions</translation>
        </message>
        <message>
            <source>Drag the tangent at q%1</source>
            <translation>Drag the tangent at q%1</translation>
        </message>
        <message>
            <source>Family: %1</source>
            <translation>Family: %1</translation>
        </message>
        <message>
            <source>Knots</source>
            <translation>Knots</translation>
        </message>
        <message>
            <source>Move the tangent at q%1</source>
            <translation>Move the tangent at q%1</translation>
        </message>
        <message>
            <source>tangent in (p′(1)), where it differs</source>
            <translation>tangent in (p′(1)), where it differs</translation>
        </message>
        <message>
            <source>tangent out (p′(0))</source>
            <translation>tangent out (p′(0))</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::DeCasteljauParameterControl</name>
        <message>
            <source>Parameter t</source>
            <translation>Parameter t</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_parameter_control.cpp" line="95" />
            <source>The parameter t ∈ [0, 1] of the curve c(t) (Def 2.4). Type a decimal or a fraction such as 1/3.</source>
            <translation>The parameter t ∈ [0, 1] of the curve c(t) (Def 2.4). Type a decimal or a fraction such as 1/3.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::DeCasteljauTab</name>
        <message>
            <source>Comb scale</source>
            <translation>Comb scale</translation>
        </message>
        <message>
            <source>scale:</source>
            <translation>scale:</translation>
        </message>
        <message>
            <source>The comb's scale must be 0 (automatic) or a positive number up to %1.</source>
            <translation>The comb's scale must be 0 (automatic) or a positive number up to %1.</translation>
        </message>
        <message>
            <source>The arc length s(t) from c(0) to c(t), the curve's length L, and the signed curvature κ(t) = (x′y″ − y′x″)/|c′|³ (positive when the curve turns left).</source>
            <translation>The arc length s(t) from c(0) to c(t), the curve's length L, and the signed curvature κ(t) = (x′y″ − y′x″)/|c′|³ (positive when the curve turns left).</translation>
        </message>
        <message>
            <source>When playing, move c(t) by equal steps of arc length instead of equal steps of t: t is not distance along the curve.</source>
            <translation>When playing, move c(t) by equal steps of arc length instead of equal steps of t: t is not distance along the curve.</translation>
        </message>
        <message>
            <source>The hodograph c′ in the corner: a Bézier curve of degree n − 1 with control points n (Pᵢ₊₁ − Pᵢ), with its own De Casteljau construction at the same t; its point is c′(t).</source>
            <translation>The hodograph c′ in the corner: a Bézier curve of degree n − 1 with control points n (Pᵢ₊₁ − Pᵢ), with its own De Casteljau construction at the same t; its point is c′(t).</translation>
        </message>
        <message>
            <source>Inflection points ○, where x′y″ − y′x″ changes sign (the curve turns the other way), and cusps ×, where c′ = 0.</source>
            <translation>Inflection points ○, where x′y″ − y′x″ changes sign (the curve turns the other way), and cusps ×, where c′ = 0.</translation>
        </message>
        <message>
            <source>The tight axis-aligned box of the curve (not of its control points), from the extrema of x(t) and y(t): the t where x′ = 0 or y′ = 0, marked ◆.</source>
            <translation>The tight axis-aligned box of the curve (not of its control points), from the extrema of x(t) and y(t): the t where x′ = 0 or y′ = 0, marked ◆.</translation>
        </message>
        <message>
            <source>Teeth along the normal, as long as |κ| times the scale given in the key, and the line through their tips: where the comb jumps, so does the curvature. No tooth where κ is undefined.</source>
            <translation>Teeth along the normal, as long as |κ| times the scale given in the key, and the line through their tips: where the comb jumps, so does the curvature. No tooth where κ is undefined.</translation>
        </message>
        <message>
            <source>The circle that fits the curve best at c(t): centre c(t) + N(t)/κ(t), radius 1/|κ(t)|. None where κ = 0 (the radius is infinite) or where κ is undefined (c′(t) = 0).</source>
            <translation>The circle that fits the curve best at c(t): centre c(t) + N(t)/κ(t), radius 1/|κ(t)|. None where κ = 0 (the radius is infinite) or where κ is undefined (c′(t) = 0).</translation>
        </message>
        <message>
            <source>The unit normal N(t) at c(t), the tangent turned a quarter turn to the left; drawn as long as the tangent's arrow. Undefined where c′(t) = 0.</source>
            <translation>The unit normal N(t) at c(t), the tangent turned a quarter turn to the left; drawn as long as the tangent's arrow. Undefined where c′(t) = 0.</translation>
        </message>
        <message>
            <source>c′(t) = %1, c″(t) = %2&lt;br&gt;x′y″ − y′x″ = %3, |c′(t)|² = %4&lt;br&gt;κ(t) = (x′y″ − y′x″)/|c′|³ = %5 ≈ %6</source>
            <translation>c′(t) = %1, c″(t) = %2&lt;br&gt;x′y″ − y′x″ = %3, |c′(t)|² = %4&lt;br&gt;κ(t) = (x′y″ − y′x″)/|c′|³ = %5 ≈ %6</translation>
        </message>
        <message>
            <source>κ(t) is undefined: c′(t) = 0 (a cusp, or coincident control points), so there is no normal and no osculating circle.</source>
            <translation>κ(t) is undefined: c′(t) = 0 (a cusp, or coincident control points), so there is no normal and no osculating circle.</translation>
        </message>
        <message>
            <source>s(t) = %1, L = %2</source>
            <translation>s(t) = %1, L = %2</translation>
        </message>
        <message>
            <source>Arc length and curvature at t</source>
            <translation>Arc length and curvature at t</translation>
        </message>
        <message>
            <source>κ(t) = %1 (radius %2)</source>
            <translation>κ(t) = %1 (radius %2)</translation>
        </message>
        <message>
            <source>κ(t) = 0: straight here, the radius is infinite</source>
            <translation>κ(t) = 0: straight here, the radius is infinite</translation>
        </message>
        <message>
            <source>κ(t) undefined: c′(t) = 0 (a cusp, or coincident control points)</source>
            <translation>κ(t) undefined: c′(t) = 0 (a cusp, or coincident control points)</translation>
        </message>
        <message>
            <source>s(t) = %1 of L = %2</source>
            <translation>s(t) = %1 of L = %2</translation>
        </message>
        <message>
            <source>hodograph c′</source>
            <translation>hodograph c′</translation>
        </message>
        <message>
            <source>○ inflections: %1 · × cusps: %2</source>
            <translation>○ inflections: %1 · × cusps: %2</translation>
        </message>
        <message>
            <source>bounding box, ◆ extrema of x and y</source>
            <translation>bounding box, ◆ extrema of x and y</translation>
        </message>
        <message>
            <source>curvature comb: teeth |κ| × %1</source>
            <translation>curvature comb: teeth |κ| × %1</translation>
        </message>
        <message>
            <source>no osculating circle: κ undefined</source>
            <translation>no osculating circle: κ undefined</translation>
        </message>
        <message>
            <source>no osculating circle: κ(t) = 0</source>
            <translation>no osculating circle: κ(t) = 0</translation>
        </message>
        <message>
            <source>osculating circle, r = 1/|κ| = %1</source>
            <translation>osculating circle, r = 1/|κ| = %1</translation>
        </message>
        <message>
            <source>no normal: c′(t) = 0</source>
            <translation>no normal: c′(t) = 0</translation>
        </message>
        <message>
            <source>unit normal N(t)</source>
            <translation>unit normal N(t)</translation>
        </message>
        <message>
            <source>tangent c′(t)/%1</source>
            <translation>tangent c′(t)/%1</translation>
        </message>
        <message>
            <source>tangent c′(t)</source>
            <translation>tangent c′(t)</translation>
        </message>
        <message>
            <source>Constant speed</source>
            <translation>Constant speed</translation>
        </message>
        <message>
            <source>Hodograph</source>
            <translation>Hodograph</translation>
        </message>
        <message>
            <source>Inflections and cusps</source>
            <translation>Inflections and cusps</translation>
        </message>
        <message>
            <source>Bounding box</source>
            <translation>Bounding box</translation>
        </message>
        <message>
            <source>Curvature comb</source>
            <translation>Curvature comb</translation>
        </message>
        <message>
            <source>Osculating circle</source>
            <translation>Osculating circle</translation>
        </message>
        <message>
            <source>Normal</source>
            <translation>Normal</translation>
        </message>
        <message numerus="yes">
            <source>Bézier curve of degree %1 with %n control point(s); t = %2, c(t) = %3.</source>
            <translation>
                <numerusform>Bézier curve of degree %1 with %n control point; t = %2, c(t) = %3.</numerusform>
                <numerusform>Bézier curve of degree %1 with %n control points; t = %2, c(t) = %3.</numerusform>
            </translation>
        </message>
        <message>
            <source>No control points.</source>
            <translation>No control points.</translation>
        </message>
        <message>
            <source>De Casteljau canvas</source>
            <translation>De Casteljau canvas</translation>
        </message>
        <message>
            <source>polygon of the half on [t, 1]</source>
            <translation>polygon of the half on [t, 1]</translation>
        </message>
        <message>
            <source>polygon of the half on [0, t]</source>
            <translation>polygon of the half on [0, t]</translation>
        </message>
        <message>
            <source>… %1 more, one colour each</source>
            <translation>… %1 more, one colour each</translation>
        </message>
        <message>
            <source>the curve of P₀…P%1</source>
            <translation>the curve of P₀…P%1</translation>
        </message>
        <message>
            <source>the point P₀ alone</source>
            <translation>the point P₀ alone</translation>
        </message>
        <message>
            <source>level %1: the points %2(t)</source>
            <translation>level %1: the points %2(t)</translation>
        </message>
        <message>
            <source>Samples: %1</source>
            <translation>Samples: %1</translation>
        </message>
        <message>
            <source>Play t</source>
            <translation>Play t</translation>
        </message>
        <message>
            <source>Move t</source>
            <translation>Move t</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="502" />
            <source>Pause</source>
            <translation>Pause</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="502" />
            <source>Play</source>
            <translation>Play</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="518" />
            <source>At most %1 control points: the degree cannot be raised further.</source>
            <translation>At most %1 control points: the degree cannot be raised further.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="524" />
            <source>Raise degree to %1</source>
            <translation>Raise degree to %1</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="525" />
            <source>Degree raised to %1: the same curve with one control point more.</source>
            <translation>Degree raised to %1: the same curve with one control point more.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="533" />
            <source>Degree %1 is high: in powers of t the condition number is %2, so only De Casteljau's algorithm, which stays stable, is used here and the exact tables are hidden.</source>
            <translation>Degree %1 is high: in powers of t the condition number is %2, so only De Casteljau's algorithm, which stays stable, is used here and the exact tables are hidden.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="552" />
            <source>The exact polynomials need control points that are small fractions: type them in the table (1/3 is accepted) or turn on Snap to grid.</source>
            <translation>The exact polynomials need control points that are small fractions: type them in the table (1/3 is accepted) or turn on Snap to grid.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="557" />
            <source>The levels in powers of t are shown up to degree %1; at degree %2 their coefficients would no longer be readable.</source>
            <translation>The levels in powers of t are shown up to degree %1; at degree %2 their coefficients would no longer be readable.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="568" />
            <source>The levels %1 in powers of t (Def 2.4)</source>
            <translation>The levels %1 in powers of t (Def 2.4)</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="601" />
            <location filename="../ui/decasteljau_tab.cpp" line="612" />
            <source>De Casteljau's triangle at t = %1 (Def 2.4)</source>
            <translation>De Casteljau's triangle at t = %1 (Def 2.4)</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="608" />
            <location filename="../ui/decasteljau_tab.cpp" line="622" />
            <source>Split at t: [0, t] has control points %1; [t, 1] has %2.</source>
            <translation>Split at t: [0, t] has control points %1; [t, 1] has %2.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="618" />
            <source>The triangle is shown up to degree %1; this curve has degree %2.</source>
            <translation>The triangle is shown up to degree %1; this curve has degree %2.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="630" />
            <source>The values are too large for a double (beyond ±1.8e308): a level of the triangle or c′(t) overflows. Move the control points closer to the origin.</source>
            <translation>The values are too large for a double (beyond ±1.8e308): a level of the triangle or c′(t) overflows. Move the control points closer to the origin.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="655" />
            <source>Animate t from 0 to 1 and around again: watch c(t) trace the curve (Def 2.4).</source>
            <translation>Animate t from 0 to 1 and around again: watch c(t) trace the curve (Def 2.4).</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="656" />
            <source>Samples:</source>
            <translation>Samples:</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="658" />
            <source>Sampling precision: the curve is drawn through this many intervals of t, like part in the thesis's Matlab De_Casteljau(P, part).</source>
            <translation>Sampling precision: the curve is drawn through this many intervals of t, like part in the thesis's Matlab De_Casteljau(P, part).</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="662" />
            <source>Raise degree</source>
            <translation>Raise degree</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="663" />
            <source>Degree elevation: the same curve written with one control point more (Qᵢ = i/(n+1) Pᵢ₋₁ + (1 − i/(n+1)) Pᵢ). Undoable.</source>
            <translation>Degree elevation: the same curve written with one control point more (Qᵢ = i/(n+1) Pᵢ₋₁ + (1 − i/(n+1)) Pᵢ). Undoable.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="665" />
            <source>Construction</source>
            <translation>Construction</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="666" />
            <source>Draw every level Pᵢʳ(t) of De Casteljau's algorithm (Def 2.4): the points of each level and the segments between them, one colour per level.</source>
            <translation>Draw every level Pᵢʳ(t) of De Casteljau's algorithm (Def 2.4): the points of each level and the segments between them, one colour per level.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="668" />
            <source>Step by step</source>
            <translation>Step by step</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="669" />
            <source>Overlay the curves of the first 1, 2, …, n+1 control points, like the desglossar option of the thesis's Matlab Rep_Bezier.</source>
            <translation>Overlay the curves of the first 1, 2, …, n+1 control points, like the desglossar option of the thesis's Matlab Rep_Bezier.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="671" />
            <source>Tangent</source>
            <translation>Tangent</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="672" />
            <source>The tangent vector c′(t) = n (P₁ⁿ⁻¹(t) − P₀ⁿ⁻¹(t)), read off the last level but one of the construction; the arrow at c(t) is c′(t)/n, that last segment.</source>
            <translation>The tangent vector c′(t) = n (P₁ⁿ⁻¹(t) − P₀ⁿ⁻¹(t)), read off the last level but one of the construction; the arrow at c(t) is c′(t)/n, that last segment.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="674" />
            <source>Split at t</source>
            <translation>Split at t</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="675" />
            <source>Split the curve at t: the two edges of De Casteljau's triangle are the control polygons of the halves [0, t] and [t, 1].</source>
            <translation>Split the curve at t: the two edges of De Casteljau's triangle are the control polygons of the halves [0, t] and [t, 1].</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="677" />
            <source>Snap to grid</source>
            <translation>Snap to grid</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="678" />
            <source>Round dragged and added points to the grid, so that they stay small fractions and the exact tables appear.</source>
            <translation>Round dragged and added points to the grid, so that they stay small fractions and the exact tables appear.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="680" />
            <source>Control points P0…Pn of the Bézier curve (Def 2.4): drag a point, double-click to add one on the nearest edge, Delete removes the selected one, arrows nudge it. Drag the curve itself to mold it, or mold it at t with Alt+arrows; near the curve its closest point and t are shown.</source>
            <translation>Control points P0…Pn of the Bézier curve (Def 2.4): drag a point, double-click to add one on the nearest edge, Delete removes the selected one, arrows nudge it. Drag the curve itself to mold it, or mold it at t with Alt+arrows; near the curve its closest point and t are shown.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="682" />
            <source>De Casteljau's triangle Pᵢʳ(t) at the current t and, for rational points, every level in powers of t, as in Ex 2.2 and Ex 2.3.</source>
            <translation>De Casteljau's triangle Pᵢʳ(t) at the current t and, for rational points, every level in powers of t, as in Ex 2.2 and Ex 2.3.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="717" />
            <source>The De Casteljau points are missing or not a list.</source>
            <translation>The De Casteljau points are missing or not a list.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="720" />
            <source>The De Casteljau tab needs between 1 and %1 control points; the document has %2.</source>
            <translation>The De Casteljau tab needs between 1 and %1 control points; the document has %2.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="728" />
            <source>Control point %1 is not a pair of finite numbers.</source>
            <translation>Control point %1 is not a pair of finite numbers.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="734" />
            <source>The parameter t must be a number between 0 and 1.</source>
            <translation>The parameter t must be a number between 0 and 1.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="741" />
            <source>The number of samples must be a whole number from %1 to %2.</source>
            <translation>The number of samples must be a whole number from %1 to %2.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="751" />
            <source>A De Casteljau display option is not true or false.</source>
            <translation>A De Casteljau display option is not true or false.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="786" />
            <source>Load Ex %1</source>
            <translation>Load Ex %1</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="789" />
            <source>Ex %1: the tables of the thesis are in the panel on the right at t = 1/2.</source>
            <translation>Ex %1: the tables of the thesis are in the panel on the right at t = 1/2.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="847" />
            <source>Drag a point; double-click to add one; Delete removes the selected point; move t with the slider.</source>
            <translation>Drag a point; double-click to add one; Delete removes the selected point; move t with the slider.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.h" line="39" />
            <source>De Casteljau</source>
            <translation>De Casteljau</translation>
        </message>
        <message>
            <source>Control points</source>
            <translation>Control points</translation>
        </message>
        <message>
            <source>Draw the control points Pᵢ, their labels and the control polygon; off, the curve alone, like puntsvis = false in the thesis&apos;s Matlab. The table still edits the points.</source>
            <translation>Draw the control points Pᵢ, their labels and the control polygon; off, the curve alone, like puntsvis = false in the thesis&apos;s Matlab. The table still edits the points.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::Document</name>
        <message>
            <source>Tab “%1”: its part of the document is not an object.</source>
            <translation>Tab “%1”: its part of the document is not an object.</translation>
        </message>
        <message>
            <source>This document has no "tabs" object holding the tabs' points and settings.</source>
            <translation>This document has no "tabs" object holding the tabs' points and settings.</translation>
        </message>
        <message>
            <source>This document's "version" is not a whole number; this Granota reads version %1.</source>
            <translation>This document's "version" is not a whole number; this Granota reads version %1.</translation>
        </message>
        <message>
            <source>This is not a Granota document: it is a JSON list, not an object.</source>
            <translation>This is not a Granota document: it is a JSON list, not an object.</translation>
        </message>
        <message>
            <location filename="../ui/document.cpp" line="33" />
            <source>This is not a Granota document: %1 (at byte %2).</source>
            <translation>This is not a Granota document: %1 (at byte %2).</translation>
        </message>
        <message>
            <location filename="../ui/document.cpp" line="40" />
            <source>This is not a Granota document (no "format": "granota").</source>
            <translation>This is not a Granota document (no "format": "granota").</translation>
        </message>
        <message>
            <location filename="../ui/document.cpp" line="45" />
            <source>This document has version %1; this Granota reads version %2.</source>
            <translation>This document has version %1; this Granota reads version %2.</translation>
        </message>
        <message>
            <location filename="../ui/document.cpp" line="61" />
            <source>Tab “%1”: %2</source>
            <translation>Tab “%1”: %2</translation>
        </message>
        <message>
            <source>This is not a Granota document: the file is empty.</source>
            <translation>This is not a Granota document: the file is empty.</translation>
        </message>
        <message>
            <source>This is not a whole Granota document: the file is cut off at byte %1.</source>
            <translation>This is not a whole Granota document: the file is cut off at byte %1.</translation>
        </message>
        <message>
            <source>This is not a Granota document: the text is not JSON at byte %1 (line %2).</source>
            <translation>This is not a Granota document: the text is not JSON at byte %1 (line %2).</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::Exporter</name>
        <message>
            <location filename="../ui/exporter.cpp" line="23" />
            <source>Cannot write “%1”.</source>
            <translation>Cannot write “%1”.</translation>
        </message>
        <message>
            <location filename="../ui/exporter.cpp" line="36" />
            <source>The resolution must be between 24 and 1200 DPI.</source>
            <translation>The resolution must be between 24 and 1200 DPI.</translation>
        </message>
        <message>
            <location filename="../ui/exporter.cpp" line="40" />
            <source>The image would be too large: choose a lower resolution.</source>
            <translation>The image would be too large: choose a lower resolution.</translation>
        </message>
        <message>
            <location filename="../ui/exporter.cpp" line="43" />
            <source>Not enough memory for an image of %1×%2 pixels.</source>
            <translation>Not enough memory for an image of %1×%2 pixels.</translation>
        </message>
        <message>
            <location filename="../ui/exporter.cpp" line="64" />
            <source>Made with Granota</source>
            <translation>Made with Granota</translation>
        </message>
        <message>
            <source>Cannot write “%1”: %2.</source>
            <translation>Cannot write “%1”: %2.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::FitExactView</name>
        <message>
            <source>M has %1 × %2 entries (a row per data point, a column per control point); the first %3 rows and %4 columns are shown.</source>
            <translation>M has %1 × %2 entries (a row per data point, a column per control point); the first %3 rows and %4 columns are shown.</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="80" />
            <source>Chord lengths dᵢ = dist(Qᵢ₋₁, Qᵢ)</source>
            <translation>Chord lengths dᵢ = dist(Qᵢ₋₁, Qᵢ)</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="92" />
            <source>The thesis (Ex 2.9) writes d₄ = √85, from (1 − 7)² + (5 + 2)²; but Q₃ has x = 8, so d₄ = √(49 + 49) = 7√2, which is used here.</source>
            <translation>The thesis (Ex 2.9) writes d₄ = √85, from (1 − 7)² + (5 + 2)²; but Q₃ has x = 8, so d₄ = √(49 + 49) = 7√2, which is used here.</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="95" />
            <source>Centripetal parameters (beyond the thesis) use √dᵢ instead of dᵢ.</source>
            <translation>Centripetal parameters (beyond the thesis) use √dᵢ instead of dᵢ.</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="107" />
            <source>Parameter correction moves the tᵢ to where the points project onto the curve: the results are shown in decimals.</source>
            <translation>Parameter correction moves the tᵢ to where the points project onto the curve: the results are shown in decimals.</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="110" />
            <source>Exact fractions are shown for up to %1 data points; these %2 are shown in decimals.</source>
            <translation>Exact fractions are shown for up to %1 data points; these %2 are shown in decimals.</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="114" />
            <source>The data are not small fractions: the results are shown in decimals.</source>
            <translation>The data are not small fractions: the results are shown in decimals.</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="120" />
            <source>These parameters are irrational (square roots of the distances), so M cannot be written in fractions: the results are shown in decimals, as the thesis does with Matlab in Ex 2.9 and Ex 2.10.</source>
            <translation>These parameters are irrational (square roots of the distances), so M cannot be written in fractions: the results are shown in decimals, as the thesis does with Matlab in Ex 2.9 and Ex 2.10.</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="124" />
            <source>MᵀM is singular for these parameters (coincident points): the control points shown are the minimum-norm least-squares solution, in decimals.</source>
            <translation>MᵀM is singular for these parameters (coincident points): the control points shown are the minimum-norm least-squares solution, in decimals.</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="125" />
            <source>The exact fractions of this fit would take too long to compute (their digits grow with the degree and the number of points): the results are shown in decimals.</source>
            <translation>The exact fractions of this fit would take too long to compute (their digits grow with the degree and the number of points): the results are shown in decimals.</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="129" />
            <location filename="../ui/fit_exact_view.cpp" line="169" />
            <source>Parameters tᵢ</source>
            <translation>Parameters tᵢ</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="136" />
            <source>Matrices (Lemma 2.2, Note 2.2)</source>
            <translation>Matrices (Lemma 2.2, Note 2.2)</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="142" />
            <source>Control points P = M⁺Q</source>
            <translation>Control points P = M⁺Q</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="150" />
            <location filename="../ui/fit_exact_view.cpp" line="191" />
            <source>Fitted curve α(t) = Σ Bⱼⁿ(t) Pⱼ</source>
            <translation>Fitted curve α(t) = Σ Bⱼⁿ(t) Pⱼ</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="156" />
            <source>Ex 2.7: the thesis prints α(t) = (−8/7 + 726/35 t − 600/35 t², 46/35 − 130/35 t + 200/35 t²), the same curve with unreduced fractions (600/35 = 120/7, 130/35 = 26/7, 200/35 = 40/7).</source>
            <translation>Ex 2.7: the thesis prints α(t) = (−8/7 + 726/35 t − 600/35 t², 46/35 − 130/35 t + 200/35 t²), the same curve with unreduced fractions (600/35 = 120/7, 130/35 = 26/7, 200/35 = 40/7).</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="160" />
            <source>Ex 2.8: the thesis prints −1636/105 as the coefficient of t in x(t). It is 3(P₁ − P₀) = 3(−3371/630 − 11/70) = −347/21 = −1735/105, shown here.</source>
            <translation>Ex 2.8: the thesis prints −1636/105 as the coefficient of t in x(t). It is 3(P₁ − P₀) = 3(−3371/630 − 11/70) = −347/21 = −1735/105, shown here.</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="175" />
            <source>Matrix M (Lemma 2.2), in decimals</source>
            <translation>Matrix M (Lemma 2.2), in decimals</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="184" />
            <source>Control points P</source>
            <translation>Control points P</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="195" />
            <source>α(t) in powers of t is not shown beyond degree %1: its coefficients grow like C(n, k) and cancel each other.</source>
            <translation>α(t) in powers of t is not shown beyond degree %1: its coefficients grow like C(n, k) and cancel each other.</translation>
        </message>
        <message>
            <source>Annex III&apos;s distances dᵢ = |Qᵢ₋₁| (BezParamProp)</source>
            <translation>Annex III&apos;s distances dᵢ = |Qᵢ₋₁| (BezParamProp)</translation>
        </message>
        <message>
            <source>Annex III&apos;s BezParamProp, as the thesis&apos;s Matlab computes it: dᵢ = |Qᵢ₋₁|, the distance of the point before from the origin, not from its neighbour — Figs 2.7 and 2.8 were drawn with these parameters (docs/thesis-errata.md).</source>
            <translation>Annex III&apos;s BezParamProp, as the thesis&apos;s Matlab computes it: dᵢ = |Qᵢ₋₁|, the distance of the point before from the origin, not from its neighbour — Figs 2.7 and 2.8 were drawn with these parameters (docs/thesis-errata.md).</translation>
        </message>
        <message>
            <source>The Penrose conditions of M⁺ (§2.1.3), checked exactly: %1</source>
            <translation>The Penrose conditions of M⁺ (§2.1.3), checked exactly: %1</translation>
        </message>
        <message>
            <source>Hessian 2MᵀM (Prop 2.2)</source>
            <translation>Hessian 2MᵀM (Prop 2.2)</translation>
        </message>
        <message>
            <source>Its eigenvalues 2σᵢ²: %1 — all positive, so the error&apos;s critical point is its minimum.</source>
            <translation>Its eigenvalues 2σᵢ²: %1 — all positive, so the error&apos;s critical point is its minimum.</translation>
        </message>
        <message>
            <source>Its eigenvalues 2σᵢ²: %1.</source>
            <translation>Its eigenvalues 2σᵢ²: %1.</translation>
        </message>
        <message>
            <source>Parameters tᵢ in radicals</source>
            <translation>Parameters tᵢ in radicals</translation>
        </message>
        <message>
            <source>in radicals</source>
            <translation>in radicals</translation>
        </message>
        <message>
            <source>decimal</source>
            <translation>decimal</translation>
        </message>
        <message>
            <source>the thesis prints</source>
            <translation>the thesis prints</translation>
        </message>
        <message>
            <source>printed − right</source>
            <translation>printed − right</translation>
        </message>
        <message>
            <source>A quotient whose denominator has more than %1 coprime radicands is left as it stands, not rationalised.</source>
            <translation>A quotient whose denominator has more than %1 coprime radicands is left as it stands, not rationalised.</translation>
        </message>
        <message>
            <source>Ex 2.9 and Ex 2.10 print tᵢ rationalised from their d₄ = √85: %1. Each is too large by the difference above (docs/thesis-errata.md, “Ex 2.9 and 2.10”).</source>
            <translation>Ex 2.9 and Ex 2.10 print tᵢ rationalised from their d₄ = √85: %1. Each is too large by the difference above (docs/thesis-errata.md, “Ex 2.9 and 2.10”).</translation>
        </message>
        <message>
            <source>The thesis (Ex 2.9) writes d₄ = √85, from (1 − 7)² + (5 + 2)²; but Q₃ has x = 8, so d₄ = √(49 + 49) = 7√2, which is used here (docs/thesis-errata.md, “Ex 2.9 and 2.10”).</source>
            <translation>The thesis (Ex 2.9) writes d₄ = √85, from (1 − 7)² + (5 + 2)²; but Q₃ has x = 8, so d₄ = √(49 + 49) = 7√2, which is used here (docs/thesis-errata.md, “Ex 2.9 and 2.10”).</translation>
        </message>
        <message>
            <source>Annex III&apos;s BezParamProp, as the thesis&apos;s Matlab computes it: dᵢ = |Qᵢ₋₁|, the distance of the point before from the origin, not from its neighbour — Figs 2.7 and 2.8 were drawn with these parameters (docs/thesis-errata.md, “Annex III”).</source>
            <translation>Annex III&apos;s BezParamProp, as the thesis&apos;s Matlab computes it: dᵢ = |Qᵢ₋₁|, the distance of the point before from the origin, not from its neighbour — Figs 2.7 and 2.8 were drawn with these parameters (docs/thesis-errata.md, “Annex III”).</translation>
        </message>
        <message>
            <source>Ex 2.7: the thesis prints α(t) = (−8/7 + 726/35 t − 600/35 t², 46/35 − 130/35 t + 200/35 t²), the same curve with unreduced fractions (600/35 = 120/7, 130/35 = 26/7, 200/35 = 40/7); its sum runs k = 0…4 where n = 2 has three control points (docs/thesis-errata.md, “Ex 2.7 and 2.8”).</source>
            <translation>Ex 2.7: the thesis prints α(t) = (−8/7 + 726/35 t − 600/35 t², 46/35 − 130/35 t + 200/35 t²), the same curve with unreduced fractions (600/35 = 120/7, 130/35 = 26/7, 200/35 = 40/7); its sum runs k = 0…4 where n = 2 has three control points (docs/thesis-errata.md, “Ex 2.7 and 2.8”).</translation>
        </message>
        <message>
            <source>Ex 2.8: the thesis prints −1636/105 as the coefficient of t in x(t). It is 3(P₁ − P₀) = 3(−3371/630 − 11/70) = −347/21 = −1735/105, shown here (docs/thesis-errata.md, “Ex 2.8”). Its sum also runs k = 0…4, with Bₖ², where n = 3 (“Ex 2.7 and 2.8”).</source>
            <translation>Ex 2.8: the thesis prints −1636/105 as the coefficient of t in x(t). It is 3(P₁ − P₀) = 3(−3371/630 − 11/70) = −347/21 = −1735/105, shown here (docs/thesis-errata.md, “Ex 2.8”). Its sum also runs k = 0…4, with Bₖ², where n = 3 (“Ex 2.7 and 2.8”).</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::FitTab</name>
        <message numerus="yes">
            <source>%n degree(s) left blank: the fit failed there.
Choose QR or SVD.</source>
            <translation>
                <numerusform>%n degree left blank: the fit failed there.
Choose QR or SVD.</numerusform>
                <numerusform>%n degrees left blank: the fit failed there.
Choose QR or SVD.</numerusform>
            </translation>
        </message>
        <message>
            <source>Comb scale</source>
            <translation>Comb scale</translation>
        </message>
        <message>
            <source>“curvatureCombScale” must be 0 (automatic) or a positive number up to %1.</source>
            <translation>“curvatureCombScale” must be 0 (automatic) or a positive number up to %1.</translation>
        </message>
        <message>
            <source>“curvatureComb” must be true or false.</source>
            <translation>“curvatureComb” must be true or false.</translation>
        </message>
        <message>
            <source>The curvature comb of the fitted curve (beyond the thesis): teeth along the normal as long as |κ| times the scale in the key, and the line through their tips; where the comb wiggles, so does the fit.</source>
            <translation>The curvature comb of the fitted curve (beyond the thesis): teeth along the normal as long as |κ| times the scale in the key, and the line through their tips; where the comb wiggles, so does the fit.</translation>
        </message>
        <message>
            <source>Curvature com&amp;b</source>
            <translation>Curvature com&amp;b</translation>
        </message>
        <message>
            <source>curvature comb of the fit: teeth |κ| × %1</source>
            <translation>curvature comb of the fit: teeth |κ| × %1</translation>
        </message>
        <message>
            <source>Curvature comb</source>
            <translation>Curvature comb</translation>
        </message>
        <message numerus="yes">
            <source>Least-squares Bézier curve of degree %1 through %n data point(s); squared error %2.</source>
            <translation>
                <numerusform>Least-squares Bézier curve of degree %1 through %n data point; squared error %2.</numerusform>
                <numerusform>Least-squares Bézier curve of degree %1 through %n data points; squared error %2.</numerusform>
            </translation>
        </message>
        <message>
            <source>Fitting canvas</source>
            <translation>Fitting canvas</translation>
        </message>
        <message>
            <source>Show matrices</source>
            <translation>Show matrices</translation>
        </message>
        <message>
            <source>Plotted up to n = %1 of %2:
refitting every degree for %3 points
on each change would slow the window.</source>
            <translation>Plotted up to n = %1 of %2:
refitting every degree for %3 points
on each change would slow the window.</translation>
        </message>
        <message>
            <source>Degree %1 is refused: the highest is %2, beyond which the Bernstein basis is too ill-conditioned for any solver.</source>
            <translation>Degree %1 is refused: the highest is %2, beyond which the Bernstein basis is too ill-conditioned for any solver.</translation>
        </message>
        <message>
            <source>The fitting tab holds %1 data points; Granota reads at most %2.</source>
            <translation>The fitting tab holds %1 data points; Granota reads at most %2.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="146" />
            <source>Drag Qᵢ: the curve is refitted as it moves; Delete removes it.</source>
            <translation>Drag Qᵢ: the curve is refitted as it moves; Delete removes it.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="174" />
            <source>Degree %1 needs %2 data points (n + 1 ≤ k + 1); there are %3, so n ≤ %4.</source>
            <translation>Degree %1 needs %2 data points (n + 1 ≤ k + 1); there are %3, so n ≤ %4.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="291" />
            <source>Degree %1</source>
            <translation>Degree %1</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="298" />
            <source>Parametrization</source>
            <translation>Parametrization</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="305" />
            <source>Solver</source>
            <translation>Solver</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="312" />
            <location filename="../ui/fit_tab.cpp" line="319" />
            <source>Parameter correction</source>
            <translation>Parameter correction</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="380" />
            <source>Least-squares fit (§2.1.3)</source>
            <translation>Least-squares fit (§2.1.3)</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="381" />
            <source>&amp;Degree n:</source>
            <translation>&amp;Degree n:</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="382" />
            <source>n: the fitted Bézier curve has n + 1 control points P₀…Pₙ, so n + 1 ≤ k + 1 data points (§2.1.3, Lemma 2.2). Ex 2.7 uses n = 2, Ex 2.8 n = 3.</source>
            <translation>n: the fitted Bézier curve has n + 1 control points P₀…Pₙ, so n + 1 ≤ k + 1 data points (§2.1.3, Lemma 2.2). Ex 2.7 uses n = 2, Ex 2.8 n = 3.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="384" />
            <source>&amp;Parameters tᵢ:</source>
            <translation>&amp;Parameters tᵢ:</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="385" />
            <source>Uniform, i/k (Ex 2.7, 2.8)</source>
            <translation>Uniform, i/k (Ex 2.7, 2.8)</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="386" />
            <source>Chord length (Ex 2.9, 2.10)</source>
            <translation>Chord length (Ex 2.9, 2.10)</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="387" />
            <source>Centripetal (beyond the thesis)</source>
            <translation>Centripetal (beyond the thesis)</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="389" />
            <source>Where on the curve each Qᵢ should fall (§2.1.3): uniform tᵢ = i/k; proportional to the chord lengths dᵢ = dist(Qᵢ₋₁, Qᵢ); or centripetal, proportional to √dᵢ.</source>
            <translation>Where on the curve each Qᵢ should fall (§2.1.3): uniform tᵢ = i/k; proportional to the chord lengths dᵢ = dist(Qᵢ₋₁, Qᵢ); or centripetal, proportional to √dᵢ.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="391" />
            <source>&amp;Solver:</source>
            <translation>&amp;Solver:</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="392" />
            <source>QR (default)</source>
            <translation>QR (default)</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="393" />
            <source>Normal equations (the thesis)</source>
            <translation>Normal equations (the thesis)</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="394" />
            <source>SVD (singular values)</source>
            <translation>SVD (singular values)</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="395" />
            <source>How MP = Q is solved in the least-squares sense. The thesis solves the normal equations MᵀM P = MᵀQ (Prop 2.2), which square the condition number; QR and SVD work on M itself and stay accurate at high degree.</source>
            <translation>How MP = Q is solved in the least-squares sense. The thesis solves the normal equations MᵀM P = MᵀQ (Prop 2.2), which square the condition number; QR and SVD work on M itself and stay accurate at high degree.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="398" />
            <source>&amp;Correct parameters, at most</source>
            <translation>&amp;Correct parameters, at most</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="399" />
            <source>Beyond the thesis: project each Qᵢ onto the fitted curve, take the new tᵢ and fit again, while the error Σ‖Qᵢ − α(tᵢ)‖² drops.</source>
            <translation>Beyond the thesis: project each Qᵢ onto the fitted curve, take the new tᵢ and fit again, while the error Σ‖Qᵢ − α(tᵢ)‖² drops.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="401" />
            <source> times</source>
            <translation> times</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="402" />
            <source>The largest number of parameter corrections (re-projection and refit).</source>
            <translation>The largest number of parameter corrections (re-projection and refit).</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="403" />
            <source>&amp;Import CSV…</source>
            <translation>&amp;Import CSV…</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="404" />
            <source>Read the data points Qᵢ from a CSV file (one “x,y” per line) or a JSON list [[x,y],…].</source>
            <translation>Read the data points Qᵢ from a CSV file (one “x,y” per line) or a JSON list [[x,y],…].</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="405" />
            <source>Show &amp;matrices</source>
            <translation>Show &amp;matrices</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="406" />
            <source>Show M (Lemma 2.2), MᵀM, (MᵀM)⁻¹ and M⁺ = (MᵀM)⁻¹Mᵀ (Note 2.2), in fractions when the data and the parameters are rational, as in Ex 2.7 and Ex 2.8.</source>
            <translation>Show M (Lemma 2.2), MᵀM, (MᵀM)⁻¹ and M⁺ = (MᵀM)⁻¹Mᵀ (Note 2.2), in fractions when the data and the parameters are rational, as in Ex 2.7 and Ex 2.8.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="408" />
            <source>Quality of the fit (Prop 2.2)</source>
            <translation>Quality of the fit (Prop 2.2)</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="409" />
            <source>The error that the least-squares curve minimises, and how sensitive the solution is to the data.</source>
            <translation>The error that the least-squares curve minimises, and how sensitive the solution is to the data.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="411" />
            <source>The data points Qᵢ (round, draggable), the fitted Bézier curve α(t), its control points Pⱼ (square) and control polygon, and the residuals Qᵢ − α(tᵢ).</source>
            <translation>The data points Qᵢ (round, draggable), the fitted Bézier curve α(t), its control points Pⱼ (square) and control polygon, and the residuals Qᵢ − α(tᵢ).</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="413" />
            <source>The parameters, the control points P = M⁺Q and the curve α(t) in powers of t, exact when possible (Ex 2.7–2.10).</source>
            <translation>The parameters, the control points P = M⁺Q and the curve α(t) in powers of t, exact when possible (Ex 2.7–2.10).</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="415" />
            <source>The least-squares error Σ‖Qᵢ − α(tᵢ)‖² of the best curve of each degree n for the current parameters (without correction); the circle marks the current n. With fixed tᵢ it can only go down as n grows, unless the solver loses accuracy.</source>
            <translation>The least-squares error Σ‖Qᵢ − α(tᵢ)‖² of the best curve of each degree n for the current parameters (without correction); the circle marks the current n. With fixed tᵢ it can only go down as n grows, unless the solver loses accuracy.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="418" />
            <source>degree n</source>
            <translation>degree n</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="419" />
            <source>squared error (log)</source>
            <translation>squared error (log)</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="421" />
            <source>Large data sets are fitted and drawn, but not listed.</source>
            <translation>Large data sets are fitted and drawn, but not listed.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="432" />
            <source>A least-squares fit needs at least 2 data points.</source>
            <translation>A least-squares fit needs at least 2 data points.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="434" />
            <source>Degree %1 needs at least %2 data points.</source>
            <translation>Degree %1 needs at least %2 data points.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="437" />
            <source>The normal equations MᵀM P = MᵀQ cannot be solved here: MᵀM is numerically singular (coincident points, or cond₂(MᵀM) = cond₂(M)² beyond 10¹⁶). Choose QR or SVD.</source>
            <translation>The normal equations MᵀM P = MᵀQ cannot be solved here: MᵀM is numerically singular (coincident points, or cond₂(MᵀM) = cond₂(M)² beyond 10¹⁶). Choose QR or SVD.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="439" />
            <source>The least-squares system has no usable solution here.</source>
            <translation>The least-squares system has no usable solution here.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="441" />
            <source>The fitted curve does not fit in double precision: lower the degree.</source>
            <translation>The fitted curve does not fit in double precision: lower the degree.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="444" />
            <source>A data point is not a finite number.</source>
            <translation>A data point is not a finite number.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="495" />
            <source>Degree lowered to %1: n + 1 control points need at least n + 1 data points, and there are %2.</source>
            <translation>Degree lowered to %1: n + 1 control points need at least n + 1 data points, and there are %2.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="546" />
            <source>Squared error Σ‖Qᵢ − α(tᵢ)‖²: %1</source>
            <translation>Squared error Σ‖Qᵢ − α(tᵢ)‖²: %1</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="547" />
            <source>RMS error √(Σ/(k+1)): %1</source>
            <translation>RMS error √(Σ/(k+1)): %1</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="548" />
            <source>Largest error max‖Qᵢ − α(tᵢ)‖: %1</source>
            <translation>Largest error max‖Qᵢ − α(tᵢ)‖: %1</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="550" />
            <source>Condition number cond₂(M): infinite (M is singular)</source>
            <translation>Condition number cond₂(M): infinite (M is singular)</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="551" />
            <source>Condition number cond₂(M): %1</source>
            <translation>Condition number cond₂(M): %1</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="553" />
            <source>Parameter corrections that lowered the error: %1</source>
            <translation>Parameter corrections that lowered the error: %1</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="556" />
            <source>⚠ Ill-conditioned: cond₂(M) ≈ %1. The control points are very sensitive to the data; lower the degree.</source>
            <translation>⚠ Ill-conditioned: cond₂(M) ≈ %1. The control points are very sensitive to the data; lower the degree.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="560" />
            <source>⚠ High degree n = %1: the Bernstein basis grows ill-conditioned (cond₂(M) ≈ %2); a lower degree or a spline is usually the better model.</source>
            <translation>⚠ High degree n = %1: the Bernstein basis grows ill-conditioned (cond₂(M) ≈ %2); a lower degree or a spline is usually the better model.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="566" />
            <source>⚠ The normal equations square the condition number: cond₂(MᵀM) ≈ %1, so about %2 of the 16 significant digits may be lost. Choose QR.</source>
            <translation>⚠ The normal equations square the condition number: cond₂(MᵀM) ≈ %1, so about %2 of the 16 significant digits may be lost. Choose QR.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="575" />
            <source>⚠ Only %1 distinct parameters tᵢ for %2 control points: M is rank deficient, and the control points shown are the minimum-norm least-squares solution.</source>
            <translation>⚠ Only %1 distinct parameters tᵢ for %2 control points: M is rank deficient, and the control points shown are the minimum-norm least-squares solution.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="580" />
            <source>No fit: %1</source>
            <translation>No fit: %1</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="593" />
            <source>All the data points coincide: the chord lengths are all zero, so uniform parameters are used instead.</source>
            <translation>All the data points coincide: the chord lengths are all zero, so uniform parameters are used instead.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="595" />
            <source>All the data points coincide: the curve is that point.</source>
            <translation>All the data points coincide: the curve is that point.</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/fit_tab.cpp" line="597" />
            <source>Q%1 and Q%2 coincide: a zero chord length gives them the same parameter tᵢ (%n such pair(s)).</source>
            <translation>
                <numerusform>Q%1 and Q%2 coincide: a zero chord length gives them the same parameter tᵢ (%n such pair(s)).</numerusform>
                <numerusform>Q%1 and Q%2 coincide: a zero chord length gives them the same parameter tᵢ (%n such pair(s)).</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="603" />
            <source>The data points are collinear: the fitted curve and its control points lie on their line.</source>
            <translation>The data points are collinear: the fitted curve and its control points lie on their line.</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/fit_tab.cpp" line="677" />
            <source>%n data points: too many to list; they are fitted and drawn.</source>
            <translation>
                <numerusform>%n data points: too many to list; they are fitted and drawn.</numerusform>
                <numerusform>%n data points: too many to list; they are fitted and drawn.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="706" />
            <source>Load Ex %1</source>
            <translation>Load Ex %1</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="707" />
            <source>Ex %1 data</source>
            <translation>Ex %1 data</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="709" />
            <source>Ex %1 settings</source>
            <translation>Ex %1 settings</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="721" />
            <source>Cannot open “%1”: %2</source>
            <translation>Cannot open “%1”: %2</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="725" />
            <source>“%1” is larger than %2 MB; Granota reads data files up to that size.</source>
            <translation>“%1” is larger than %2 MB; Granota reads data files up to that size.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="735" />
            <source>“%1” holds no valid data points, nothing was changed: %2</source>
            <translation>“%1” holds no valid data points, nothing was changed: %2</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/fit_tab.cpp" line="740" />
            <source>“%1” has %n point(s); a fit needs at least 2, nothing was changed.</source>
            <translation>
                <numerusform>“%1” has %n point(s); a fit needs at least 2, nothing was changed.</numerusform>
                <numerusform>“%1” has %n point(s); a fit needs at least 2, nothing was changed.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="747" />
            <source>“%1” has a coordinate too large for a double; nothing was changed.</source>
            <translation>“%1” has a coordinate too large for a double; nothing was changed.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="751" />
            <source>Import %1</source>
            <translation>Import %1</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/fit_tab.cpp" line="754" />
            <source>Imported %n data points from “%1”.</source>
            <translation>
                <numerusform>Imported %n data points from “%1”.</numerusform>
                <numerusform>Imported %n data points from “%1”.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="760" />
            <location filename="../ui/fit_tab.cpp" line="767" />
            <source>Import data points</source>
            <translation>Import data points</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="761" />
            <source>Point files (*.csv *.txt *.json);;All files (*)</source>
            <translation>Point files (*.csv *.txt *.json);;All files (*)</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="789" />
            <source>The fitting tab's data points are missing or not a list.</source>
            <translation>The fitting tab's data points are missing or not a list.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="798" />
            <source>Data point Q%1 is not a pair of finite numbers.</source>
            <translation>Data point Q%1 is not a pair of finite numbers.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="804" />
            <source>The fitting tab needs at least 2 data points.</source>
            <translation>The fitting tab needs at least 2 data points.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="812" />
            <source>The degree must be a whole number from 0 to %1.</source>
            <translation>The degree must be a whole number from 0 to %1.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="821" />
            <source>Unknown parametrization “%1”.</source>
            <translation>Unknown parametrization “%1”.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="830" />
            <source>Unknown solver “%1”.</source>
            <translation>Unknown solver “%1”.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="837" />
            <source>“correctParameters” must be true or false.</source>
            <translation>“correctParameters” must be true or false.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="845" />
            <source>The number of parameter corrections must be a whole number from 1 to %1.</source>
            <translation>The number of parameter corrections must be a whole number from 1 to %1.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="852" />
            <source>“showMatrices” must be true or false.</source>
            <translation>“showMatrices” must be true or false.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="858" />
            <source>Open fitting data</source>
            <translation>Open fitting data</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="859" />
            <source>Open data points</source>
            <translation>Open data points</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="861" />
            <source>Open fitting settings</source>
            <translation>Open fitting settings</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="960" />
            <source>Drag a data point Qᵢ and the curve is refitted; double-click adds a point, Delete removes it.</source>
            <translation>Drag a data point Qᵢ and the curve is refitted; double-click adds a point, Delete removes it.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.h" line="40" />
            <source>Fitting</source>
            <translation>Fitting</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Cancel</translation>
        </message>
        <message>
            <source>Stop correcting the parameters: the curve shown is then the best fit found so far.</source>
            <translation>Stop correcting the parameters: the curve shown is then the best fit found so far.</translation>
        </message>
        <message>
            <source>Cancelling: the fit stops after the correction under way…</source>
            <translation>Cancelling: the fit stops after the correction under way…</translation>
        </message>
        <message>
            <source>Fitting in the background: %1 of at most %2 parameter corrections made…</source>
            <translation>Fitting in the background: %1 of at most %2 parameter corrections made…</translation>
        </message>
        <message>
            <source>Fitting in the background…</source>
            <translation>Fitting in the background…</translation>
        </message>
        <message>
            <source>Cancelled after %1 of at most %2 parameter corrections: the curve shown is the best fit found until then.</source>
            <translation>Cancelled after %1 of at most %2 parameter corrections: the curve shown is the best fit found until then.</translation>
        </message>
        <message>
            <source>Fit cancelled: the curve shown is the best fit found so far.</source>
            <translation>Fit cancelled: the curve shown is the best fit found so far.</translation>
        </message>
        <message>
            <source>Annex III (BezParamProp)</source>
            <translation>Annex III (BezParamProp)</translation>
        </message>
        <message>
            <source>Where on the curve each Qᵢ should fall (§2.1.3): uniform tᵢ = i/k; proportional to the chord lengths dᵢ = dist(Qᵢ₋₁, Qᵢ); centripetal, proportional to √dᵢ; or as Annex III&apos;s BezParamProp computes them, with |Qᵢ₋₁| in place of dᵢ (how Figs 2.7 and 2.8 were drawn).</source>
            <translation>Where on the curve each Qᵢ should fall (§2.1.3): uniform tᵢ = i/k; proportional to the chord lengths dᵢ = dist(Qᵢ₋₁, Qᵢ); centripetal, proportional to √dᵢ; or as Annex III&apos;s BezParamProp computes them, with |Qᵢ₋₁| in place of dᵢ (how Figs 2.7 and 2.8 were drawn).</translation>
        </message>
        <message>
            <source>Control points</source>
            <translation>Control points</translation>
        </message>
        <message>
            <source>Residuals</source>
            <translation>Residuals</translation>
        </message>
        <message>
            <source>Step by step</source>
            <translation>Step by step</translation>
        </message>
        <message>
            <source>Every parametrization in the plot</source>
            <translation>Every parametrization in the plot</translation>
        </message>
        <message>
            <source>Samples: %1</source>
            <translation>Samples: %1</translation>
        </message>
        <message>
            <source>Drawing</source>
            <translation>Drawing</translation>
        </message>
        <message>
            <source>Con&amp;trol points</source>
            <translation>Con&amp;trol points</translation>
        </message>
        <message>
            <source>Draw the fitted control points Pⱼ (squares), their labels and the control polygon. The thesis&apos;s Figs 2.5–2.8 show the curve and the data alone.</source>
            <translation>Draw the fitted control points Pⱼ (squares), their labels and the control polygon. The thesis&apos;s Figs 2.5–2.8 show the curve and the data alone.</translation>
        </message>
        <message>
            <source>&amp;Residuals</source>
            <translation>&amp;Residuals</translation>
        </message>
        <message>
            <source>Draw the segments from α(tᵢ) to each data point Qᵢ: the errors the fit minimises.</source>
            <translation>Draw the segments from α(tᵢ) to each data point Qᵢ: the errors the fit minimises.</translation>
        </message>
        <message>
            <source>Step by st&amp;ep</source>
            <translation>Step by st&amp;ep</translation>
        </message>
        <message>
            <source>Also draw the Bézier curves of the first 1, 2, …, n+1 fitted control points, thinner and lighter, like the desglossar option of the thesis&apos;s Matlab Rep_BezParamEqui and Rep_BezParamProp (Annex III).</source>
            <translation>Also draw the Bézier curves of the first 1, 2, …, n+1 fitted control points, thinner and lighter, like the desglossar option of the thesis&apos;s Matlab Rep_BezParamEqui and Rep_BezParamProp (Annex III).</translation>
        </message>
        <message>
            <source>Samp&amp;les:</source>
            <translation>Samp&amp;les:</translation>
        </message>
        <message>
            <source>Sampling precision: the fitted curve is drawn through this many intervals of t, like part in the thesis&apos;s Matlab Rep_BezParamEqui(Q, n, part, desglossar).</source>
            <translation>Sampling precision: the fitted curve is drawn through this many intervals of t, like part in the thesis&apos;s Matlab Rep_BezParamEqui(Q, n, part, desglossar).</translation>
        </message>
        <message>
            <source>Every parametri&amp;zation in the error plot</source>
            <translation>Every parametri&amp;zation in the error plot</translation>
        </message>
        <message>
            <source>Plot the error against the degree for uniform, chord-length, centripetal and Annex III parameters at once, one line each, to see where each wins.</source>
            <translation>Plot the error against the degree for uniform, chord-length, centripetal and Annex III parameters at once, one line each, to see where each wins.</translation>
        </message>
        <message>
            <source>uniform</source>
            <translation>uniform</translation>
        </message>
        <message>
            <source>chord length</source>
            <translation>chord length</translation>
        </message>
        <message>
            <source>centripetal</source>
            <translation>centripetal</translation>
        </message>
        <message>
            <source>Annex III</source>
            <translation>Annex III</translation>
        </message>
        <message>
            <source>“samples” must be a whole number from %1 to %2.</source>
            <translation>“samples” must be a whole number from %1 to %2.</translation>
        </message>
        <message>
            <source>“%1” must be true or false.</source>
            <translation>“%1” must be true or false.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::FrogCanvas</name>
        <message numerus="yes">
            <source>Broad phase: %n candidate pairs, %1 contacts</source>
            <translation>
                <numerusform>Broad phase: %n candidate pair, %1 contacts</numerusform>
                <numerusform>Broad phase: %n candidate pairs, %1 contacts</numerusform>
            </translation>
        </message>
        <message>
            <source>Broad phase: none, the seed has no collisions (§5.2 is future work)</source>
            <translation>Broad phase: none, the seed has no collisions (§5.2 is future work)</translation>
        </message>
        <message>
            <source>Shift+click on a vertex or a joint to follow it with the trail.</source>
            <translation>Shift+click on a vertex or a joint to follow it with the trail.</translation>
        </message>
        <message>
            <source>Trail of vertex %1 of body %2 (Shift+click a point to follow another)</source>
            <translation>Trail of vertex %1 of body %2 (Shift+click a point to follow another)</translation>
        </message>
        <message>
            <source>Trail of joint %1 of chain %2 (Shift+click a point to follow another)</source>
            <translation>Trail of joint %1 of chain %2 (Shift+click a point to follow another)</translation>
        </message>
        <message>
            <source>The ghost starts with the next Reset: the run so far is too long to replay for it.</source>
            <translation>The ghost starts with the next Reset: the run so far is too long to replay for it.</translation>
        </message>
        <message>
            <source>The other solver cannot run this scene: %1</source>
            <translation>The other solver cannot run this scene: %1</translation>
        </message>
        <message>
            <source>Dashed ghost: the stable solver fed the same mouse</source>
            <translation>Dashed ghost: the stable solver fed the same mouse</translation>
        </message>
        <message>
            <source>Dashed ghost: the seed solver fed the same mouse</source>
            <translation>Dashed ghost: the seed solver fed the same mouse</translation>
        </message>
        <message>
            <source>Dashed ghost: the stable solver fed the same mouse, area error %1 %</source>
            <translation>Dashed ghost: the stable solver fed the same mouse, area error %1 %</translation>
        </message>
        <message>
            <source>Dashed ghost: the seed solver fed the same mouse, area error %1 %</source>
            <translation>Dashed ghost: the seed solver fed the same mouse, area error %1 %</translation>
        </message>
        <message>
            <source>Playing the recorded run back: move the cursor inside a body to take over from step %1.</source>
            <translation>Playing the recorded run back: move the cursor inside a body to take over from step %1.</translation>
        </message>
        <message>
            <source>Playing the recorded run back: press inside a body to take over from step %1.</source>
            <translation>Playing the recorded run back: press inside a body to take over from step %1.</translation>
        </message>
        <message>
            <source>Replaying the recorded run, step %1 of %2: a press on a body takes over from there</source>
            <translation>Replaying the recorded run, step %1 of %2: a press on a body takes over from there</translation>
        </message>
        <message numerus="yes">
            <source>Fast, %1× real time: %n steps a frame</source>
            <translation>
                <numerusform>Fast, %1× real time: %n step a frame</numerusform>
                <numerusform>Fast, %1× real time: %n steps a frame</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Slow motion, %1× real time: one step every %n frames, the step itself unchanged</source>
            <translation>
                <numerusform>Slow motion, %1× real time: one step every %n frame, the step itself unchanged</numerusform>
                <numerusform>Slow motion, %1× real time: one step every %n frames, the step itself unchanged</numerusform>
            </translation>
        </message>
        <message>
            <source>%1; area error %2 %.</source>
            <translation>%1; area error %2 %.</translation>
        </message>
        <message>
            <source>Nothing to grab here: move the cursor inside the body with the arrows.</source>
            <translation>Nothing to grab here: move the cursor inside the body with the arrows.</translation>
        </message>
        <message>
            <source>Top of the frame: the scene's upper wall (y = 0)</source>
            <translation>Top of the frame: the scene's upper wall (y = 0)</translation>
        </message>
        <message>
            <source>The body has blown up (area error %1 %): press Reset (R), or switch to the Stable solver</source>
            <translation>The body has blown up (area error %1 %): press Reset (R), or switch to the Stable solver</translation>
        </message>
        <message>
            <source>Area error, mean of the %1 bodies, %2 % · largest stretch %3 %</source>
            <translation>Area error, mean of the %1 bodies, %2 % · largest stretch %3 %</translation>
        </message>
        <message>
            <source>Body 1 of %1: area %2 px² · target %3 px²</source>
            <translation>Body 1 of %1: area %2 px² · target %3 px²</translation>
        </message>
        <message>
            <source>Body 1 of %1: area %2 px² · target %3 px² (%4 %)</source>
            <translation>Body 1 of %1: area %2 px² · target %3 px² (%4 %)</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/frog_canvas.cpp" line="232" />
            <source>Running %n× slower than real time: a step of this scene is more work than a frame holds</source>
            <translation>
                <numerusform>Running %n× slower than real time: a step of this scene is more work than a frame holds</numerusform>
                <numerusform>Running %n× slower than real time: a step of this scene is more work than a frame holds</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/frog_canvas.cpp" line="227" />
            <source>Least-squares Bézier fit, degree %1 through %2 points: %3 µs per frame</source>
            <translation>Least-squares Bézier fit, degree %1 through %2 points: %3 µs per frame</translation>
        </message>
        <message>
            <location filename="../ui/frog_canvas.cpp" line="232" />
            <source>Precomputed Bézier points (§4.9): computed once, nothing per frame</source>
            <translation>Precomputed Bézier points (§4.9): computed once, nothing per frame</translation>
        </message>
        <message>
            <location filename="../ui/frog_canvas.cpp" line="237" />
            <source>Area %1 px² · target %2 px² (%3 %)</source>
            <translation>Area %1 px² · target %2 px² (%3 %)</translation>
        </message>
        <message>
            <location filename="../ui/frog_canvas.cpp" line="240" />
            <source>Area %1 px² · target %2 px²</source>
            <translation>Area %1 px² · target %2 px²</translation>
        </message>
        <message>
            <location filename="../ui/frog_canvas.cpp" line="244" />
            <source>Area error %1 % · largest stretch %2 %</source>
            <translation>Area error %1 % · largest stretch %2 %</translation>
        </message>
        <message>
            <location filename="../ui/frog_canvas.cpp" line="246" />
            <source>Largest correction %1 · kinetic energy %2 · potential energy %3</source>
            <translation>Largest correction %1 · kinetic energy %2 · potential energy %3</translation>
        </message>
        <message>
            <location filename="../ui/frog_canvas.cpp" line="250" />
            <source>Velocities: this scene has no soft body</source>
            <translation>Velocities: this scene has no soft body</translation>
        </message>
        <message>
            <location filename="../ui/frog_canvas.cpp" line="253" />
            <source>Frame %1 ms (%2 frames per second) · step %3 ms · drawing %4 ms</source>
            <translation>Frame %1 ms (%2 frames per second) · step %3 ms · drawing %4 ms</translation>
        </message>
        <message>
            <location filename="../ui/frog_canvas.cpp" line="257" />
            <source>Paused · step %1 ms · drawing %2 ms</source>
            <translation>Paused · step %1 ms · drawing %2 ms</translation>
        </message>
        <message>
            <location filename="../ui/frog_canvas.cpp" line="258" />
            <source>Step %1</source>
            <translation>Step %1</translation>
        </message>
        <message>
            <location filename="../ui/frog_canvas.cpp" line="670" />
            <source>Press inside the body to grab it.</source>
            <translation>Press inside the body to grab it.</translation>
        </message>
        <message>
            <source>Ruler: %1. Esc or a right click clears it.</source>
            <translation>Ruler: %1. Esc or a right click clears it.</translation>
        </message>
        <message>
            <source>%1 px (Δx %2, Δy %3)</source>
            <translation>%1 px (Δx %2, Δy %3)</translation>
        </message>
        <message>
            <source>Protractor: no joint of this scene has angle limits</source>
            <translation>Protractor: no joint of this scene has angle limits</translation>
        </message>
        <message numerus="yes">
            <source>Protractor: %n of %1 joints held at a limit (red)</source>
            <translation>
                <numerusform>Protractor: %n of %1 joints held at a limit (red)</numerusform>
                <numerusform>Protractor: %n of %1 joints held at a limit (red)</numerusform>
            </translation>
        </message>
        <message>
            <source>Ruler: move the cursor with the arrows to the other end, then L.</source>
            <translation>Ruler: move the cursor with the arrows to the other end, then L.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::FrogParametersPanel</name>
        <message>
            <source>%1, %2</source>
            <translation>%1, %2</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="267" />
            <source>px</source>
            <translation>px</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="269" />
            <source>px/step²</source>
            <translation>px/step²</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="271" />
            <source>px/step</source>
            <translation>px/step</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="273" />
            <source>px²</source>
            <translation>px²</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="281" />
            <source>Sides N</source>
            <translation>Sides N</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="282" />
            <source>Radius r</source>
            <translation>Radius r</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="283" />
            <source>Centre (x, y)</source>
            <translation>Centre (x, y)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="284" />
            <source>Frame width</source>
            <translation>Frame width</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="285" />
            <source>Frame height</source>
            <translation>Frame height</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="286" />
            <source>Gravity g (x, y)</source>
            <translation>Gravity g (x, y)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="287" />
            <source>Initial velocity v₀ (x, y)</source>
            <translation>Initial velocity v₀ (x, y)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="288" />
            <source>Friction f (x, y)</source>
            <translation>Friction f (x, y)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="289" />
            <source>Largest move velmax</source>
            <translation>Largest move velmax</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="290" />
            <source>Spring length</source>
            <translation>Spring length</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="291" />
            <source>Target area</source>
            <translation>Target area</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="292" />
            <source>Area factor C</source>
            <translation>Area factor C</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="293" />
            <source>Grab</source>
            <translation>Grab</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="294" />
            <source>Bodies</source>
            <translation>Bodies</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="295" />
            <source>Bézier points</source>
            <translation>Bézier points</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="296" />
            <source>Fit degree n</source>
            <translation>Fit degree n</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="298" />
            <source>Front legs (upper, lower)</source>
            <translation>Front legs (upper, lower)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="298" />
            <source>Back legs (upper, lower)</source>
            <translation>Back legs (upper, lower)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="299" />
            <source>Link %1</source>
            <translation>Link %1</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="301" />
            <source>Front right shoulder (min, max)</source>
            <translation>Front right shoulder (min, max)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="302" />
            <source>Front left shoulder (min, max)</source>
            <translation>Front left shoulder (min, max)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="303" />
            <source>Back right shoulder (min, max)</source>
            <translation>Back right shoulder (min, max)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="304" />
            <source>Back left shoulder (min, max)</source>
            <translation>Back left shoulder (min, max)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="305" />
            <source>Front elbows (min, max)</source>
            <translation>Front elbows (min, max)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="306" />
            <source>Back elbows (min, max)</source>
            <translation>Back elbows (min, max)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="307" />
            <source>Shoulder (min, max)</source>
            <translation>Shoulder (min, max)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="308" />
            <source>Elbow (min, max)</source>
            <translation>Elbow (min, max)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="316" />
            <source>N (costats): the vertices of the body, a regular polygon built from the top (§4.1). Annex II's frog has N = 10; try 3 to 200. Up to 10000, 100000 vertices in all: beyond about 3000 the stable solver runs slower than real time.</source>
            <translation>N (costats): the vertices of the body, a regular polygon built from the top (§4.1). Annex II's frog has N = 10; try 3 to 200. Up to 10000, 100000 vertices in all: beyond about 3000 the stable solver runs slower than real time.</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="319" />
            <source>r: distance from the centre to each vertex of the starting polygon (§4.1). Annex II takes r = |height/6| from the frame, and so does the scene until a value is set here.</source>
            <translation>r: distance from the centre to each vertex of the starting polygon (§4.1). Annex II takes r = |height/6| from the frame, and so does the scene until a value is set here.</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="321" />
            <source>(c₁, c₂): where the first body starts, in pixels of the frame (y grows downwards). Annex II starts at the frame’s centre, and so does the scene until a value is set here.</source>
            <translation>(c₁, c₂): where the first body starts, in pixels of the frame (y grows downwards). Annex II starts at the frame’s centre, and so does the scene until a value is set here.</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="323" />
            <source>The frame (Processing's size(1280, 720)): vertices stay inside [0, width − 1] × [0, height − 1] (§4.2).</source>
            <translation>The frame (Processing's size(1280, 720)): vertices stay inside [0, width − 1] × [0, height − 1] (§4.2).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="325" />
            <source>g (gravetat): acceleration added to every vertex each step, v(t) = v(t − 1) + g (§4.2).</source>
            <translation>g (gravetat): acceleration added to every vertex each step, v(t) = v(t − 1) + g (§4.2).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="327" />
            <source>v⁰ (velocitat inicial): the velocity the body starts with (§4.2).</source>
            <translation>v⁰ (velocitat inicial): the velocity the body starts with (§4.2).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="329" />
            <source>f (fregament): share of the velocity kept per step on each axis, f ∈ ]0, 1[ (§4.3).</source>
            <translation>f (fregament): share of the velocity kept per step on each axis, f ∈ ]0, 1[ (§4.3).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="331" />
            <source>velmax: the largest move of a vertex in one step, per axis (Annex II).</source>
            <translation>velmax: the largest move of a vertex in one step, per axis (Annex II).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="333" />
            <source>molls: rest length of every edge spring; the springs pull the edges back towards it (§4.4).</source>
            <translation>molls: rest length of every edge spring; the springs pull the edges back towards it (§4.4).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="335" />
            <source>Areal: the area the body tries to keep, by the trapezoid rule and edge normals (§4.5). 0 or huge values are allowed.</source>
            <translation>Areal: the area the body tries to keep, by the trapezoid rule and edge normals (§4.5). 0 or huge values are allowed.</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="338" />
            <source>C (reescala): how strongly each step corrects the area; large values make a stiff body (§4.5).</source>
            <translation>C (reescala): how strongly each step corrects the area; large values make a stiff body (§4.5).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="340" />
            <source>Which vertices hold on to the mouse: all of them (§4.6), those above the grab point (§4.7), or Annex II's fixed anchors {0, 1, N−1, N} (§4.10).</source>
            <translation>Which vertices hold on to the mouse: all of them (§4.6), those above the grab point (§4.7), or Annex II's fixed anchors {0, 1, N−1, N} (§4.10).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="343" />
            <source>How many bodies fall and collide (§5.2.2); a broad phase keeps the cost close to linear.</source>
            <translation>How many bodies fall and collide (§5.2.2); a broad phase keeps the cost close to linear.</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="345" />
            <source>§4.9: the polygon is the control polygon of one Bézier curve, sampled once at this many points by De Casteljau (Def 2.4); the samples become the body's vertices.</source>
            <translation>§4.9: the polygon is the control polygon of one Bézier curve, sampled once at this many points by De Casteljau (Def 2.4); the samples become the body's vertices.</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="348" />
            <source>§4.9, the abandoned option: the degree n of the least-squares Bézier curve fitted to the outline every frame (Lemma 2.2, Prop 2.2).</source>
            <translation>§4.9, the abandoned option: the degree n of the least-squares Bézier curve fitted to the outline every frame (Lemma 2.2, Prop 2.2).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="351" />
            <source>longit: lengths of the two segments of each leg, shoulder–elbow and elbow–wrist (§4.16, Annex II).</source>
            <translation>longit: lengths of the two segments of each leg, shoulder–elbow and elbow–wrist (§4.16, Annex II).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="353" />
            <source>Length of this link of the pendulum; the links keep their length exactly (§4.13, §4.14).</source>
            <translation>Length of this link of the pendulum; the links keep their length exactly (§4.13, §4.14).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="356" />
            <source>angles: smallest and largest angle between the two segments at the elbow, in degrees (§4.15; Annex II uses ±π/12 in front, ±π/3 behind).</source>
            <translation>angles: smallest and largest angle between the two segments at the elbow, in degrees (§4.15; Annex II uses ±π/12 in front, ±π/3 behind).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="358" />
            <source>anglesc: smallest and largest angle of the upper segment at the shoulder, in degrees (§4.15; Annex II uses 0 to π and −π to 0).</source>
            <translation>anglesc: smallest and largest angle of the upper segment at the shoulder, in degrees (§4.15; Annex II uses 0 to π and −π to 0).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="375" />
            <source>All vertices (§4.6)</source>
            <translation>All vertices (§4.6)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="376" />
            <source>Above the mouse (§4.7)</source>
            <translation>Above the mouse (§4.7)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="377" />
            <source>Anchors {0, 1, N−1, N} (§4.10)</source>
            <translation>Anchors {0, 1, N−1, N} (§4.10)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="383" />
            <source>The obstacles come from the scene file.</source>
            <translation>The obstacles come from the scene file.</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="384" />
            <source>The shapes of the bodies come from the scene file.</source>
            <translation>The shapes of the bodies come from the scene file.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::FrogTab</name>
        <message numerus="yes">
            <source>The scene starts again; Undo brings back the run of %n step(s) it replaced.</source>
            <translation>
                <numerusform>The scene starts again; Undo brings back the run of %n step it replaced.</numerusform>
                <numerusform>The scene starts again; Undo brings back the run of %n steps it replaced.</numerusform>
            </translation>
        </message>
        <message>
            <source>A dashpot along each edge, as a damping ratio: 0 none, 1 critical (an edge stretched and let go comes back without ringing), above 1 slower still. What it takes shows in the plots as damping. The run goes on with it from the next step, and the recording keeps the change.</source>
            <translation>A dashpot along each edge, as a damping ratio: 0 none, 1 critical (an edge stretched and let go comes back without ringing), above 1 slower still. What it takes shows in the plots as damping. The run goes on with it from the next step, and the recording keeps the change.</translation>
        </message>
        <message>
            <source>Edge damping ratio ζ</source>
            <translation>Edge damping ratio ζ</translation>
        </message>
        <message>
            <source>The same stiffness as a frequency, as Box2D states its soft constraints: how many times a second an edge of this body rings on its own (α = 0, rigid, rings at none). Setting it sets the compliance.</source>
            <translation>The same stiffness as a frequency, as Box2D states its soft constraints: how many times a second an edge of this body rings on its own (α = 0, rigid, rings at none). Setting it sets the compliance.</translation>
        </message>
        <message>
            <source> Hz</source>
            <translation> Hz</translation>
        </message>
        <message>
            <source>Edge frequency f</source>
            <translation>Edge frequency f</translation>
        </message>
        <message>
            <source>§5.2.2: the pairs of bodies whose boxes overlap, the only ones tested for contact (a uniform grid finds them), and how many contacts there are (stable solver).</source>
            <translation>§5.2.2: the pairs of bodies whose boxes overlap, the only ones tested for contact (a uniform grid finds them), and how many contacts there are (stable solver).</translation>
        </message>
        <message>
            <source>Broad phase</source>
            <translation>Broad phase</translation>
        </message>
        <message>
            <source>The path of one point over the last 10 s: the pendulum's tip or the first body's vertex 0; Shift+click on a vertex or a joint to follow it.</source>
            <translation>The path of one point over the last 10 s: the pendulum's tip or the first body's vertex 0; Shift+click on a vertex or a joint to follow it.</translation>
        </message>
        <message>
            <source>Trail</source>
            <translation>Trail</translation>
        </message>
        <message>
            <source>Stopwatch: marked step %1; M again clears the mark.</source>
            <translation>Stopwatch: marked step %1; M again clears the mark.</translation>
        </message>
        <message>
            <source>Marks the step shown; the label then counts the steps and seconds since it, as the run goes on or the timeline moves (M). Again: clears the mark.</source>
            <translation>Marks the step shown; the label then counts the steps and seconds since it, as the run goes on or the timeline moves (M). Again: clears the mark.</translation>
        </message>
        <message>
            <source>Stopwatch</source>
            <translation>Stopwatch</translation>
        </message>
        <message numerus="yes">
            <source>%1 s (%n steps) before step %2</source>
            <translation>
                <numerusform>%1 s (%n step) before step %2</numerusform>
                <numerusform>%1 s (%n steps) before step %2</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%1 s (%n steps) since step %2</source>
            <translation>
                <numerusform>%1 s (%n step) since step %2</numerusform>
                <numerusform>%1 s (%n steps) since step %2</numerusform>
            </translation>
        </message>
        <message>
            <source>Both solvers at once: the other solver runs the same scene, fed the same mouse, and is drawn dashed over this one (the seed's frog sits about 17 % short of its area, the stable one holds it).</source>
            <translation>Both solvers at once: the other solver runs the same scene, fed the same mouse, and is drawn dashed over this one (the seed's frog sits about 17 % short of its area, the stable one holds it).</translation>
        </message>
        <message>
            <source>Ghost of the other solver</source>
            <translation>Ghost of the other solver</translation>
        </message>
        <message>
            <source>This scene has no springs: the compliance and the damping ratio do nothing here.</source>
            <translation>This scene has no springs: the compliance and the damping ratio do nothing here.</translation>
        </message>
        <message>
            <source>α = 0: the edges are rigid.</source>
            <translation>α = 0: the edges are rigid.</translation>
        </message>
        <message>
            <source>An edge of %1 px rings with a period of %2 steps (%3 Hz at 60 steps a second); 0 makes the edges rigid.</source>
            <translation>An edge of %1 px rings with a period of %2 steps (%3 Hz at 60 steps a second); 0 makes the edges rigid.</translation>
        </message>
        <message>
            <source>The soft-body report below the tab: XPBD's constraint error against the substeps and their cost (View ▸ Error against run time).</source>
            <translation>The soft-body report below the tab: XPBD's constraint error against the substeps and their cost (View ▸ Error against run time).</translation>
        </message>
        <message>
            <source>Error against substeps…</source>
            <translation>Error against substeps…</translation>
        </message>
        <message>
            <source>How soft the body's edges are, in step² per unit of mass and per px of rest length: 0 is rigid, larger is softer. Unlike the seed's factors it does not depend on the substeps or the number of vertices. The run goes on with it from the next step, and the recording keeps the change.</source>
            <translation>How soft the body's edges are, in step² per unit of mass and per px of rest length: 0 is rigid, larger is softer. Unlike the seed's factors it does not depend on the substeps or the number of vertices. The run goes on with it from the next step, and the recording keeps the change.</translation>
        </message>
        <message>
            <source>Edge compliance α</source>
            <translation>Edge compliance α</translation>
        </message>
        <message>
            <source>Substeps per step, 1 to 32: each step is cut into n substeps, and the constraints' error falls like 1/n² at a cost proportional to n. The run goes on with it from the next step, and the recording keeps the change.</source>
            <translation>Substeps per step, 1 to 32: each step is cut into n substeps, and the constraints' error falls like 1/n² at a cost proportional to n. The run goes on with it from the next step, and the recording keeps the change.</translation>
        </message>
        <message>
            <source>Substeps n</source>
            <translation>Substeps n</translation>
        </message>
        <message>
            <source>Stable solver</source>
            <translation>Stable solver</translation>
        </message>
        <message>
            <source>The same scene and values on the stable solver (XPBD), which holds them.</source>
            <translation>The same scene and values on the stable solver (XPBD), which holds them.</translation>
        </message>
        <message>
            <source>Use the Stable solver</source>
            <translation>Use the Stable solver</translation>
        </message>
        <message>
            <source>The body has blown up.</source>
            <translation>The body has blown up.</translation>
        </message>
        <message>
            <source>The run was saved at step %1: drag the timeline to go there (it is long to replay).</source>
            <translation>The run was saved at step %1: drag the timeline to go there (it is long to replay).</translation>
        </message>
        <message>
            <source>The frog's recording was refused: %1</source>
            <translation>The frog's recording was refused: %1</translation>
        </message>
        <message>
            <source>Step 0: the run starts here.</source>
            <translation>Step 0: the run starts here.</translation>
        </message>
        <message>
            <source>Step %1 of %2 · %3 s</source>
            <translation>Step %1 of %2 · %3 s</translation>
        </message>
        <message>
            <source>Timeline</source>
            <translation>Timeline</translation>
        </message>
        <message>
            <source>The run so far, step by step: drag to go back to any step (the run pauses there). Running on replays what was recorded until a press on a body, a spawn or a change takes over (, one step back, . one step on).</source>
            <translation>The run so far, step by step: drag to go back to any step (the run pauses there). Running on replays what was recorded until a press on a body, a spawn or a change takes over (, one step back, . one step on).</translation>
        </message>
        <message>
            <source>Under the canvas: the energies, what damping and the rest took, the area error, the largest stretch and the contacts as the run goes on; the pendulums' phase plot. Pause freezes them; they export as CSV.</source>
            <translation>Under the canvas: the energies, what damping and the rest took, the area error, the largest stretch and the contacts as the run goes on; the pendulums' phase plot. Pause freezes them; they export as CSV.</translation>
        </message>
        <message>
            <source>Plots over time</source>
            <translation>Plots over time</translation>
        </message>
        <message>
            <source>The speed must be one of 0.125, 0.25, 0.5, 1, 2 and 4.</source>
            <translation>The speed must be one of 0.125, 0.25, 0.5, 1, 2 and 4.</translation>
        </message>
        <message>
            <source>Slow motion steps once every few frames and fast runs several steps a frame: the step itself never changes, so the seed goes through exactly the states of Annex II ([ slower, ] faster).</source>
            <translation>Slow motion steps once every few frames and fast runs several steps a frame: the step itself never changes, so the seed goes through exactly the states of Annex II ([ slower, ] faster).</translation>
        </message>
        <message>
            <source>Speed</source>
            <translation>Speed</translation>
        </message>
        <message>
            <source>Scene %1, %2 solver</source>
            <translation>Scene %1, %2 solver</translation>
        </message>
        <message>
            <source>Frog canvas</source>
            <translation>Frog canvas</translation>
        </message>
        <message>
            <source>Drag the body with the mouse; Space on the canvas spawns one at the mouse. P pauses, S steps, R resets.</source>
            <translation>Drag the body with the mouse; Space on the canvas spawns one at the mouse. P pauses, S steps, R resets.</translation>
        </message>
        <message>
            <source>Solver: %1</source>
            <translation>Solver: %1</translation>
        </message>
        <message>
            <source>Stage: %1</source>
            <translation>Stage: %1</translation>
        </message>
        <message>
            <source>The seed solver has no angle constraints: these shapes round into blobs. The Stable solver keeps their form.</source>
            <translation>The seed solver has no angle constraints: these shapes round into blobs. The Stable solver keeps their form.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="229" />
            <location filename="../ui/frog_tab.cpp" line="560" />
            <source>Cost of the fit: %1 µs per frame.</source>
            <translation>Cost of the fit: %1 µs per frame.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="264" />
            <source>The simulation cannot be built with these values: %1</source>
            <translation>The simulation cannot be built with these values: %1</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="280" />
            <source>Unknown scene “%1”. The scenes are: %2.</source>
            <translation>Unknown scene “%1”. The scenes are: %2.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="330" />
            <source>The scene starts again.</source>
            <translation>The scene starts again.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="382" />
            <location filename="../ui/frog_tab.cpp" line="641" />
            <source>Scene “%1” has no parameter “%2”.</source>
            <translation>Scene “%1” has no parameter “%2”.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="391" />
            <location filename="../ui/frog_tab.cpp" line="649" />
            <source>This value was refused: %1</source>
            <translation>This value was refused: %1</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="409" />
            <source>Change %1</source>
            <translation>Change %1</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="447" />
            <source>Polygon and mouse</source>
            <translation>Polygon and mouse</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="448" />
            <source>Gravity</source>
            <translation>Gravity</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="449" />
            <source>Bounce</source>
            <translation>Bounce</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="450" />
            <source>Springs</source>
            <translation>Springs</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="451" />
            <source>Area</source>
            <translation>Area</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="452" />
            <source>Verlet and grabbing</source>
            <translation>Verlet and grabbing</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="453" />
            <source>Tuned parameters</source>
            <translation>Tuned parameters</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="454" />
            <source>Colour fill</source>
            <translation>Colour fill</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="455" />
            <source>Bézier outline</source>
            <translation>Bézier outline</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="456" />
            <source>Revised Bézier</source>
            <translation>Revised Bézier</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="457" />
            <source>Catmull-Rom outline</source>
            <translation>Catmull-Rom outline</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="458" />
            <source>Pendulum</source>
            <translation>Pendulum</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="459" />
            <source>Chain of joints</source>
            <translation>Chain of joints</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="460" />
            <source>Angle limits</source>
            <translation>Angle limits</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="461" />
            <source>The frog</source>
            <translation>The frog</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="462" />
            <source>Obstacles</source>
            <translation>Obstacles</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="463" />
            <source>Many bodies</source>
            <translation>Many bodies</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="464" />
            <source>Other shapes</source>
            <translation>Other shapes</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="471" />
            <source>A regular polygon drawn with straight lines; its radius follows the mouse, r = |mouseY − h/2|.</source>
            <translation>A regular polygon drawn with straight lines; its radius follows the mouse, r = |mouseY − h/2|.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="473" />
            <source>Every vertex falls with constant acceleration (MRUA) and stops at the edge of the frame.</source>
            <translation>Every vertex falls with constant acceleration (MRUA) and stops at the edge of the frame.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="475" />
            <source>At the frame the velocity turns round and keeps a share f of itself; a click starts the polygon again at the mouse.</source>
            <translation>At the frame the velocity turns round and keeps a share f of itself; a click starts the polygon again at the mouse.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="478" />
            <source>Springs along the edges pull each pair of neighbours back towards their rest length.</source>
            <translation>Springs along the edges pull each pair of neighbours back towards their rest length.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="480" />
            <source>The area, by the trapezoid rule, is pushed back towards the target along the edge normals.</source>
            <translation>The area, by the trapezoid rule, is pushed back towards the target along the edge normals.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="482" />
            <source>Verlet integration (Def 3.1). Press inside the body to grab it: every vertex is tied to the mouse.</source>
            <translation>Verlet integration (Def 3.1). Press inside the body to grab it: every vertex is tied to the mouse.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="484" />
            <source>Only the vertices above the grab point hold on to the mouse.</source>
            <translation>Only the vertices above the grab point hold on to the mouse.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="486" />
            <source>The same body, filled with colour.</source>
            <translation>The same body, filled with colour.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="488" />
            <source>The polygon's vertices are the control points of one Bézier curve, sampled once. Beside it, the per-frame least-squares fit that the thesis abandoned, with its cost.</source>
            <translation>The polygon's vertices are the control points of one Bézier curve, sampled once. Beside it, the per-frame least-squares fit that the thesis abandoned, with its cost.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="491" />
            <source>Tuned constants, and fixed anchors for grabbing, on the precomputed Bézier points.</source>
            <translation>Tuned constants, and fixed anchors for grabbing, on the precomputed Bézier points.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="493" />
            <source>The outline is a Catmull-Rom curve through the vertices (τ = 1/2, Processing's curveVertex).</source>
            <translation>The outline is a Catmull-Rom curve through the vertices (τ = 1/2, Processing's curveVertex).</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="495" />
            <source>A double pendulum hanging from the mouse; its lengths are restored at once.</source>
            <translation>A double pendulum hanging from the mouse; its lengths are restored at once.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="497" />
            <source>A chain of joints following its first joint: each joint is put back at its distance from the previous one.</source>
            <translation>A chain of joints following its first joint: each joint is put back at its distance from the previous one.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="500" />
            <source>A leg: two links with gravity, the frame, and limits on the angles at its joints.</source>
            <translation>A leg: two links with gravity, the frame, and limits on the angles at its joints.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="502" />
            <source>Body, four legs and head: the final program of Annex II.</source>
            <translation>Body, four legs and head: the final program of Annex II.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="504" />
            <source>Fixed segments and polygons that the bodies collide with (future work, §5.2).</source>
            <translation>Fixed segments and polygons that the bodies collide with (future work, §5.2).</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="506" />
            <source>Several bodies collide with each other; a broad phase keeps the cost close to linear.</source>
            <translation>Several bodies collide with each other; a broad phase keeps the cost close to linear.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="508" />
            <source>Bodies that are not regular polygons, kept in shape by angle constraints between their edges.</source>
            <translation>Bodies that are not regular polygons, kept in shape by angle constraints between their edges.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="515" />
            <source>The pendulum hangs from the mouse: move the mouse over the picture.</source>
            <translation>The pendulum hangs from the mouse: move the mouse over the picture.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="518" />
            <source>Move the mouse up and down: the radius is r = |mouseY − h/2| (§4.1).</source>
            <translation>Move the mouse up and down: the radius is r = |mouseY − h/2| (§4.1).</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="520" />
            <source>Click to start the polygon again at the mouse (§4.3).</source>
            <translation>Click to start the polygon again at the mouse (§4.3).</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="521" />
            <source>Reset (R) drops the polygon again.</source>
            <translation>Reset (R) drops the polygon again.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="523" />
            <source>Drag the body with the left button. Space drops a new one at the mouse and holds it until you let go (Annex II).</source>
            <translation>Drag the body with the left button. Space drops a new one at the mouse and holds it until you let go (Annex II).</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="529" />
            <source>Scene</source>
            <translation>Scene</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="530" />
            <source>Stage</source>
            <translation>Stage</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="533" />
            <source>The stages of chapter 4, in the thesis's order, and the future work of §5.2. Each scene builds, draws and shows only its own components.</source>
            <translation>The stages of chapter 4, in the thesis's order, and the future work of §5.2. Each scene builds, draws and shows only its own components.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="536" />
            <source>Solver</source>
            <translation>Solver</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="537" />
            <source>Seed (Annex II)</source>
            <translation>Seed (Annex II)</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="538" />
            <source>Stable (XPBD)</source>
            <translation>Stable (XPBD)</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="539" />
            <source>Seed: the thesis's own schemes, reproduced faithfully (Annex II). Stable: beyond the thesis, position-based constraints with compliance (XPBD) that hold the target area and stay stable on stiff and extreme settings. Switching starts the scene again.</source>
            <translation>Seed: the thesis's own schemes, reproduced faithfully (Annex II). Stable: beyond the thesis, position-based constraints with compliance (XPBD) that hold the target area and stay stable on stiff and extreme settings. Switching starts the scene again.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="542" />
            <source>Run</source>
            <translation>Run</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="542" />
            <source>Pause</source>
            <translation>Pause</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="543" />
            <source>Pause or run the animation, one fixed step per frame at 60 frames per second (P).</source>
            <translation>Pause or run the animation, one fixed step per frame at 60 frames per second (P).</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="544" />
            <source>Step</source>
            <translation>Step</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="545" />
            <source>One fixed step, as one call of actualitza() in Annex II; pauses first (S or .).</source>
            <translation>One fixed step, as one call of actualitza() in Annex II; pauses first (S or .).</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="546" />
            <source>Reset</source>
            <translation>Reset</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="547" />
            <source>Start the scene again with the current parameters (R).</source>
            <translation>Start the scene again with the current parameters (R).</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="549" />
            <source>Bézier outline (§4.9)</source>
            <translation>Bézier outline (§4.9)</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="550" />
            <source>Precomputed points</source>
            <translation>Precomputed points</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="551" />
            <source>The thesis's choice (§4.9, §4.10): the polygon is the control polygon of a Bézier curve sampled once by De Casteljau (Def 2.4); the samples are the body's vertices.</source>
            <translation>The thesis's choice (§4.9, §4.10): the polygon is the control polygon of a Bézier curve sampled once by De Casteljau (Def 2.4); the samples are the body's vertices.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="553" />
            <source>Least-squares fit every frame</source>
            <translation>Least-squares fit every frame</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="554" />
            <source>The option §4.9 abandoned as too costly for Processing: every frame, the least-squares Bézier curve through the outline (Lemma 2.2, Prop 2.2). With M⁺ computed once, a frame costs one small matrix product; the curve need not pass through the vertices (Note 2.3).</source>
            <translation>The option §4.9 abandoned as too costly for Processing: every frame, the least-squares Bézier curve through the outline (Lemma 2.2, Prop 2.2). With M⁺ computed once, a frame costs one small matrix product; the curve need not pass through the vertices (Note 2.3).</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="558" />
            <source>Precomputed points: nothing to compute per frame.</source>
            <translation>Precomputed points: nothing to compute per frame.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="562" />
            <source>Parameters</source>
            <translation>Parameters</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="563" />
            <source>Only this scene's parameters, with the names of Annex II. Changes apply at once: the scene starts again with them.</source>
            <translation>Only this scene's parameters, with the names of Annex II. Changes apply at once: the scene starts again with them.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="567" />
            <source>Overlays</source>
            <translation>Overlays</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="568" />
            <source>Vertices</source>
            <translation>Vertices</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="569" />
            <source>The body's vertices, numbered as in Annex II's arrays (v₀ under the head), and the joints of the legs.</source>
            <translation>The body's vertices, numbered as in Annex II's arrays (v₀ under the head), and the joints of the legs.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="572" />
            <source>The polygon's edges: the springs of §4.4 that keep neighbours at their length.</source>
            <translation>The polygon's edges: the springs of §4.4 that keep neighbours at their length.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="573" />
            <source>Area vs target</source>
            <translation>Area vs target</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="574" />
            <source>The body's area by the trapezoid rule against the target area (§4.5); the bar's mark is the target.</source>
            <translation>The body's area by the trapezoid rule against the target area (§4.5); the bar's mark is the target.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="576" />
            <source>Velocities</source>
            <translation>Velocities</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="577" />
            <source>Each vertex's move in the last step, x − x_prev (Verlet, Def 3.1), drawn four times longer.</source>
            <translation>Each vertex's move in the last step, x − x_prev (Verlet, Def 3.1), drawn four times longer.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="579" />
            <source>Readouts</source>
            <translation>Readouts</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="580" />
            <source>What the solver measures: area error, largest stretch of an edge, largest correction or constraint force, kinetic and potential energy.</source>
            <translation>What the solver measures: area error, largest stretch of an edge, largest correction or constraint force, kinetic and potential energy.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="582" />
            <source>Frame time</source>
            <translation>Frame time</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="583" />
            <source>Time per frame and per simulation step, in milliseconds, averaged a few times a second.</source>
            <translation>Time per frame and per simulation step, in milliseconds, averaged a few times a second.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="617" />
            <source>The scene “%1” cannot be loaded: %2</source>
            <translation>The scene “%1” cannot be loaded: %2</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="625" />
            <source>Unknown solver “%1” (seed or stable).</source>
            <translation>Unknown solver “%1” (seed or stable).</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="633" />
            <source>The frog's parameters must be an object.</source>
            <translation>The frog's parameters must be an object.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="658" />
            <source>The frog's overlays must be an object.</source>
            <translation>The frog's overlays must be an object.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="670" />
            <source>The overlay “%1” must be true or false.</source>
            <translation>The overlay “%1” must be true or false.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="680" />
            <source>The Bézier outline must be “precomputed” or “fit”, not “%1”.</source>
            <translation>The Bézier outline must be “precomputed” or “fit”, not “%1”.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="688" />
            <source>“paused” must be true or false.</source>
            <translation>“paused” must be true or false.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="795" />
            <source>The number of frames must be at least 1.</source>
            <translation>The number of frames must be at least 1.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="797" />
            <source>Cannot create the folder “%1”.</source>
            <translation>Cannot create the folder “%1”.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="811" />
            <source>Cannot write “%1”.</source>
            <translation>Cannot write “%1”.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.h" line="33" />
            <source>Frog</source>
            <translation>Frog</translation>
        </message>
        <message>
            <source>The stable solver's knobs were refused: substeps from %1 to %2, compliance from 0 to %3, damping ratio from 0 to %4.</source>
            <translation>The stable solver's knobs were refused: substeps from %1 to %2, compliance from 0 to %3, damping ratio from 0 to %4.</translation>
        </message>
        <message>
            <source>Protractor</source>
            <translation>Protractor</translation>
        </message>
        <message>
            <source>§4.15: each joint's angle, in degrees, over the range its limits allow (shaded); red when the joint is held at a limit.</source>
            <translation>§4.15: each joint's angle, in degrees, over the range its limits allow (shaded); red when the joint is held at a limit.</translation>
        </message>
        <message>
            <source>The ruler must be four numbers: x and y of each end, in px.</source>
            <translation>The ruler must be four numbers: x and y of each end, in px.</translation>
        </message>
        <message>
            <source>The run from before this step was not kept (too much memory): the scene starts again.</source>
            <translation>The run from before this step was not kept (too much memory): the scene starts again.</translation>
        </message>
        <message>
            <source>There is no scene to export.</source>
            <translation>There is no scene to export.</translation>
        </message>
        <message>
            <source>Step %1 is no longer recorded.</source>
            <translation>Step %1 is no longer recorded.</translation>
        </message>
        <message>
            <source>Keys: the arrows move the cursor, G grabs, L lays a ruler, Space spawns a body; P pauses, S steps, R resets.</source>
            <translation>Keys: the arrows move the cursor, G grabs, L lays a ruler, Space spawns a body; P pauses, S steps, R resets.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::MainWindow</name>
        <message>
            <source>&lt;p&gt;Everything can be done with the keyboard alone: Help ▸ Keyboard shortcuts lists every key.&lt;/p&gt;</source>
            <translation>&lt;p&gt;Everything can be done with the keyboard alone: Help ▸ Keyboard shortcuts lists every key.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Tabs</source>
            <translation>Tabs</translation>
        </message>
        <message>
            <source>Keyboard shortcuts</source>
            <translation>Keyboard shortcuts</translation>
        </message>
        <message>
            <source>&amp;Keyboard shortcuts</source>
            <translation>&amp;Keyboard shortcuts</translation>
        </message>
        <message>
            <source>Pre&amp;vious tab</source>
            <translation>Pre&amp;vious tab</translation>
        </message>
        <message>
            <source>&amp;Next tab</source>
            <translation>&amp;Next tab</translation>
        </message>
        <message>
            <source>&amp;Redo %1</source>
            <translation>&amp;Redo %1</translation>
        </message>
        <message>
            <source>&amp;Undo %1</source>
            <translation>&amp;Undo %1</translation>
        </message>
        <message>
            <source>A Granota session was closed without saving its changes to “%1” (autosaved %2). Recover them?</source>
            <translation>A Granota session was closed without saving its changes to “%1” (autosaved %2). Recover them?</translation>
        </message>
        <message>
            <source>A Granota session was closed without saving its Untitled document (autosaved %1). Recover it?</source>
            <translation>A Granota session was closed without saving its Untitled document (autosaved %1). Recover it?</translation>
        </message>
        <message>
            <source>&amp;Discard</source>
            <translation>&amp;Discard</translation>
        </message>
        <message>
            <source>&amp;Keep for later</source>
            <translation>&amp;Keep for later</translation>
        </message>
        <message>
            <source>&amp;Recover</source>
            <translation>&amp;Recover</translation>
        </message>
        <message>
            <source>Recovered %1. Not recovered:
%2

The whole autosave is kept as “%3”.</source>
            <translation>Recovered %1. Not recovered:
%2

The whole autosave is kept as “%3”.</translation>
        </message>
        <message>
            <source>Recovered the unsaved work of the last session. The autosave is kept as “%1”.</source>
            <translation>Recovered the unsaved work of the last session. The autosave is kept as “%1”.</translation>
        </message>
        <message>
            <source>The autosave could not be recovered: %1

It is kept as “%2”.</source>
            <translation>The autosave could not be recovered: %1

It is kept as “%2”.</translation>
        </message>
        <message>
            <source>no tab's part could be read.</source>
            <translation>no tab's part could be read.</translation>
        </message>
        <message>
            <source>Granota cannot keep a copy of your unsaved changes: %1

Save the document (Ctrl+S) to keep them. Granota will keep trying.</source>
            <translation>Granota cannot keep a copy of your unsaved changes: %1

Save the document (Ctrl+S) to keep them. Granota will keep trying.</translation>
        </message>
        <message>
            <source>Autosave failed</source>
            <translation>Autosave failed</translation>
        </message>
        <message>
            <source>⚠ Not autosaved: save your work</source>
            <translation>⚠ Not autosaved: save your work</translation>
        </message>
        <message>
            <source>The autosave works again.</source>
            <translation>The autosave works again.</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="156" />
            <source>Loaded Ex %1 of the thesis.</source>
            <translation>Loaded Ex %1 of the thesis.</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="248" />
            <source>Ex %1 could not be loaded.</source>
            <translation>Ex %1 could not be loaded.</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="307" />
            <source>&amp;File</source>
            <translation>&amp;File</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="308" />
            <source>&amp;New</source>
            <translation>&amp;New</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="309" />
            <source>&amp;Open…</source>
            <translation>&amp;Open…</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="310" />
            <source>Open &amp;Recent</source>
            <translation>Open &amp;Recent</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="311" />
            <source>&amp;Save</source>
            <translation>&amp;Save</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="312" />
            <source>Save &amp;As…</source>
            <translation>Save &amp;As…</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="313" />
            <source>&amp;Export</source>
            <translation>&amp;Export</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="314" />
            <source>PNG image…</source>
            <translation>PNG image…</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="315" />
            <source>SVG drawing…</source>
            <translation>SVG drawing…</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="316" />
            <source>PDF document…</source>
            <translation>PDF document…</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="317" />
            <source>CSV data…</source>
            <translation>CSV data…</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="318" />
            <source>TikZ picture for LaTeX…</source>
            <translation>TikZ picture for LaTeX…</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="319" />
            <source>Frog animation as PNG frames…</source>
            <translation>Frog animation as PNG frames…</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="320" />
            <source>&amp;Quit</source>
            <translation>&amp;Quit</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="321" />
            <source>&amp;Edit</source>
            <translation>&amp;Edit</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="322" />
            <source>&amp;Undo</source>
            <translation>&amp;Undo</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="323" />
            <source>&amp;Redo</source>
            <translation>&amp;Redo</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="324" />
            <source>&amp;View</source>
            <translation>&amp;View</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="325" />
            <source>&amp;Presentation mode</source>
            <translation>&amp;Presentation mode</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="326" />
            <source>Full screen, larger text and thicker lines for the classroom.</source>
            <translation>Full screen, larger text and thicker lines for the classroom.</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="327" />
            <source>&amp;Error against run time</source>
            <translation>&amp;Error against run time</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="328" />
            <source>Show, below the tab, how accurate each numerical method is for the time it takes (work-precision plot).</source>
            <translation>Show, below the tab, how accurate each numerical method is for the time it takes (work-precision plot).</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="330" />
            <source>Zoom &amp;in</source>
            <translation>Zoom &amp;in</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="331" />
            <source>Zoom &amp;out</source>
            <translation>Zoom &amp;out</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="332" />
            <source>&amp;Fit to view</source>
            <translation>&amp;Fit to view</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="334" />
            <source>Show %1</source>
            <translation>Show %1</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="337" />
            <source>&amp;Language</source>
            <translation>&amp;Language</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="338" />
            <source>E&amp;xamples</source>
            <translation>E&amp;xamples</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="340" />
            <source>Ex 2.1 — Cubic spline through four points (Def 2.3)</source>
            <translation>Ex 2.1 — Cubic spline through four points (Def 2.3)</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="341" />
            <source>Ex 2.2 — De Casteljau, degree 4</source>
            <translation>Ex 2.2 — De Casteljau, degree 4</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="342" />
            <source>Ex 2.3 — De Casteljau, a closed curve of degree 4</source>
            <translation>Ex 2.3 — De Casteljau, a closed curve of degree 4</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="343" />
            <source>Ex 2.4 — Bernstein polynomials up to degree 5</source>
            <translation>Ex 2.4 — Bernstein polynomials up to degree 5</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="344" />
            <source>Ex 2.5 — Ex 2.2's curve in the Bernstein basis</source>
            <translation>Ex 2.5 — Ex 2.2's curve in the Bernstein basis</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="345" />
            <source>Ex 2.6 — Ex 2.3's curve in the Bernstein basis</source>
            <translation>Ex 2.6 — Ex 2.3's curve in the Bernstein basis</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="346" />
            <source>Ex 2.7 — Least squares, degree 2, uniform parameters</source>
            <translation>Ex 2.7 — Least squares, degree 2, uniform parameters</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="347" />
            <source>Ex 2.8 — Least squares, degree 3, uniform parameters</source>
            <translation>Ex 2.8 — Least squares, degree 3, uniform parameters</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="348" />
            <source>Ex 2.9 — Least squares, degree 2, chord lengths</source>
            <translation>Ex 2.9 — Least squares, degree 2, chord lengths</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="349" />
            <source>Ex 2.10 — Least squares, degree 3, chord lengths</source>
            <translation>Ex 2.10 — Least squares, degree 3, chord lengths</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="350" />
            <source>Ex 2.11 — A Catmull-Rom segment for τ = 0, 1/2, 2</source>
            <translation>Ex 2.11 — A Catmull-Rom segment for τ = 0, 1/2, 2</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="351" />
            <source>Ex 2.12 — Blending functions for several tensions</source>
            <translation>Ex 2.12 — Blending functions for several tensions</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="352" />
            <source>Ex 2.13 — Catmull-Rom curve, cyclic and open</source>
            <translation>Ex 2.13 — Catmull-Rom curve, cyclic and open</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="356" />
            <source>&amp;Help</source>
            <translation>&amp;Help</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="357" />
            <source>&amp;User guide</source>
            <translation>&amp;User guide</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="358" />
            <source>&amp;About Granota</source>
            <translation>&amp;About Granota</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="359" />
            <source>Position of the mouse in the plane</source>
            <translation>Position of the mouse in the plane</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="387" />
            <source>Untitled</source>
            <translation>Untitled</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="388" />
            <source>%1%2 — Granota</source>
            <translation>%1%2 — Granota</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="395" />
            <source>Unsaved changes</source>
            <translation>Unsaved changes</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="396" />
            <source>The document has unsaved changes. Save them?</source>
            <translation>The document has unsaved changes. Save them?</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="424" />
            <source>Cannot open “%1”: %2</source>
            <translation>Cannot open “%1”: %2</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="428" />
            <source>“%1” is too large for a Granota document.</source>
            <translation>“%1” is too large for a Granota document.</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="450" />
            <source>Cannot write “%1”.</source>
            <translation>Cannot write “%1”.</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="465" />
            <location filename="../ui/main_window.cpp" line="471" />
            <location filename="../ui/main_window.cpp" line="519" />
            <source>Open document</source>
            <translation>Open document</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="466" />
            <source>Granota documents (*.granota);;All files (*)</source>
            <translation>Granota documents (*.granota);;All files (*)</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="478" />
            <location filename="../ui/main_window.cpp" line="487" />
            <source>Save document</source>
            <translation>Save document</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="479" />
            <source>Granota documents (*.granota)</source>
            <translation>Granota documents (*.granota)</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="490" />
            <source>Saved %1</source>
            <translation>Saved %1</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="547" />
            <location filename="../ui/main_window.cpp" line="561" />
            <source>Recover unsaved work</source>
            <translation>Recover unsaved work</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="548" />
            <source>Granota was closed without saving the last changes. Recover them?</source>
            <translation>Granota was closed without saving the last changes. Recover them?</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="559" />
            <source>Recovered the unsaved work of the last session.</source>
            <translation>Recovered the unsaved work of the last session.</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="561" />
            <source>The autosave could not be read.</source>
            <translation>The autosave could not be read.</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="581" />
            <source>No tab is shown.</source>
            <translation>No tab is shown.</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="582" />
            <source>Granota — %1</source>
            <translation>Granota — %1</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="593" />
            <source>Unknown export format “%1”.</source>
            <translation>Unknown export format “%1”.</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="606" />
            <source>Export PNG</source>
            <translation>Export PNG</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="607" />
            <source>Resolution (dots per inch; 300 for print):</source>
            <translation>Resolution (dots per inch; 300 for print):</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="615" />
            <location filename="../ui/main_window.cpp" line="623" />
            <source>Export</source>
            <translation>Export</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="616" />
            <source>%1 files (*.%2)</source>
            <translation>%1 files (*.%2)</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="621" />
            <source>Exported %1</source>
            <translation>Exported %1</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="630" />
            <location filename="../ui/main_window.cpp" line="641" />
            <source>Frog animation</source>
            <translation>Frog animation</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="630" />
            <source>Number of frames (60 per second):</source>
            <translation>Number of frames (60 per second):</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="634" />
            <source>Folder for the frames</source>
            <translation>Folder for the frames</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/main_window.cpp" line="639" />
            <source>Wrote %n frames.</source>
            <translation>
                <numerusform>Wrote %n frame.</numerusform>
                <numerusform>Wrote %n frames.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="700" />
            <source>User guide</source>
            <translation>User guide</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="702" />
            <source>&lt;h3&gt;Granota in five tabs&lt;/h3&gt;&lt;p&gt;&lt;b&gt;De Casteljau&lt;/b&gt; (§2.1.1): drag the control points, move t, watch every level.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Bernstein&lt;/b&gt; (§2.1.2): the basis polynomials and their weights at the same t.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Fitting&lt;/b&gt; (§2.1.3): a Bézier curve through data by least squares.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Catmull-Rom&lt;/b&gt; (§2.2): curves through the points, one per tension τ.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Frog&lt;/b&gt; (chapter 4): the soft body, stage by stage.&lt;/p&gt;&lt;p&gt;Double-click to add a point, Delete to remove it, arrows to nudge it, Ctrl+Z to undo. The Examples menu loads every worked example of chapter 2. F11 switches presentation mode.&lt;/p&gt;</source>
            <translation>&lt;h3&gt;Granota in five tabs&lt;/h3&gt;&lt;p&gt;&lt;b&gt;De Casteljau&lt;/b&gt; (§2.1.1): drag the control points, move t, watch every level.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Bernstein&lt;/b&gt; (§2.1.2): the basis polynomials and their weights at the same t.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Fitting&lt;/b&gt; (§2.1.3): a Bézier curve through data by least squares.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Catmull-Rom&lt;/b&gt; (§2.2): curves through the points, one per tension τ.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Frog&lt;/b&gt; (chapter 4): the soft body, stage by stage.&lt;/p&gt;&lt;p&gt;Double-click to add a point, Delete to remove it, arrows to nudge it, Ctrl+Z to undo. The Examples menu loads every worked example of chapter 2. F11 switches presentation mode.&lt;/p&gt;</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="716" />
            <source>About Granota</source>
            <translation>About Granota</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="717" />
            <source>&lt;h3&gt;Granota&lt;/h3&gt;&lt;p&gt;Splines and soft bodies for the classroom, from the thesis “Animació procedimental per a cossos tous”.&lt;/p&gt;</source>
            <translation>&lt;h3&gt;Granota&lt;/h3&gt;&lt;p&gt;Splines and soft bodies for the classroom, from the thesis “Animació procedimental per a cossos tous”.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Cannot save “%1”: %2. The file on disk is unchanged, and your changes are still here: save them elsewhere (Save As).</source>
            <translation>Cannot save “%1”: %2. The file on disk is unchanged, and your changes are still here: save them elsewhere (Save As).</translation>
        </message>
        <message>
            <source>Cannot save “%1”: %2. Your changes are still here: save them elsewhere (Save As).</source>
            <translation>Cannot save “%1”: %2. Your changes are still here: save them elsewhere (Save As).</translation>
        </message>
        <message>
            <source>“%1” has changed on disk since this window opened or saved it — in another window or another program. Saving replaces those changes with this window&apos;s.</source>
            <translation>“%1” has changed on disk since this window opened or saved it — in another window or another program. Saving replaces those changes with this window&apos;s.</translation>
        </message>
        <message>
            <source>&amp;Replace it</source>
            <translation>&amp;Replace it</translation>
        </message>
        <message>
            <source>“%1” already exists. Replace it?</source>
            <translation>“%1” already exists. Replace it?</translation>
        </message>
        <message>
            <source>The autosave could not be recovered: %1

It is no longer on disk.</source>
            <translation>The autosave could not be recovered: %1

It is no longer on disk.</translation>
        </message>
        <message>
            <source>Recovered %1. Not recovered:
%2</source>
            <translation>Recovered %1. Not recovered:
%2</translation>
        </message>
        <message>
            <source>Thesis &amp;figures…</source>
            <translation>Thesis &amp;figures…</translation>
        </message>
        <message>
            <source>&lt;p&gt;Where a printed example of the thesis slips, the tab says so beside the right value; docs/thesis-errata.md, in Granota&apos;s sources, lists every slip and where Granota shows it.&lt;/p&gt;</source>
            <translation>&lt;p&gt;Where a printed example of the thesis slips, the tab says so beside the right value; docs/thesis-errata.md, in Granota&apos;s sources, lists every slip and where Granota shows it.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>%1 × %2 pixels</source>
            <translation>%1 × %2 pixels</translation>
        </message>
        <message>
            <source>Size of the frames (video):</source>
            <translation>Size of the frames (video):</translation>
        </message>
        <message>
            <source>&amp;Side panel</source>
            <translation>&amp;Side panel</translation>
        </message>
        <message>
            <source>The settings and results beside the canvas; presentation mode folds them away so that the canvas has the width.</source>
            <translation>The settings and results beside the canvas; presentation mode folds them away so that the canvas has the width.</translation>
        </message>
        <message>
            <source>&amp;Blank the screen</source>
            <translation>&amp;Blank the screen</translation>
        </message>
        <message>
            <source>Black over the whole window until B again or a click (a presenter remote&apos;s blank key).</source>
            <translation>Black over the whole window until B again or a click (a presenter remote&apos;s blank key).</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::PointEditor</name>
        <message>
            <source>Past %1 points the labels are hidden and the handles small, unless this is on.</source>
            <translation>Past %1 points the labels are hidden and the handles small, unless this is on.</translation>
        </message>
        <message>
            <source>Hide point labels</source>
            <translation>Hide point labels</translation>
        </message>
        <message>
            <source>Show point labels</source>
            <translation>Show point labels</translation>
        </message>
        <message numerus="yes">
            <source>%n points: their labels are hidden and their handles small, so that the curve shows; right-click the canvas ▸ Show point labels to see them.</source>
            <translation>
                <numerusform>%n points: their labels are hidden and their handles small, so that the curve shows; right-click the canvas ▸ Show point labels to see them.</numerusform>
                <numerusform>%n points: their labels are hidden and their handles small, so that the curve shows; right-click the canvas ▸ Show point labels to see them.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/point_editor.cpp" line="81" />
            <source>Refused: a point is not a finite number.</source>
            <translation>Refused: a point is not a finite number.</translation>
        </message>
        <message>
            <location filename="../ui/point_editor.cpp" line="92" />
            <source>Refused: a coordinate must be a finite number.</source>
            <translation>Refused: a coordinate must be a finite number.</translation>
        </message>
        <message>
            <location filename="../ui/point_editor.cpp" line="97" />
            <location filename="../ui/point_editor.cpp" line="264" />
            <source>Move point %1</source>
            <translation>Move point %1</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/point_editor.cpp" line="103" />
            <source>At most %n points here.</source>
            <translation>
                <numerusform>At most %n point here.</numerusform>
                <numerusform>At most %n points here.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/point_editor.cpp" line="111" />
            <source>Add point</source>
            <translation>Add point</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/point_editor.cpp" line="120" />
            <source>At least %n points are needed here.</source>
            <translation>
                <numerusform>At least %n point are needed here.</numerusform>
                <numerusform>At least %n points are needed here.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/point_editor.cpp" line="125" />
            <source>Delete point %1</source>
            <translation>Delete point %1</translation>
        </message>
        <message>
            <location filename="../ui/point_editor.cpp" line="213" />
            <source>Delete %1%2</source>
            <translation>Delete %1%2</translation>
        </message>
        <message>
            <location filename="../ui/point_editor.cpp" line="215" />
            <source>Add a point here</source>
            <translation>Add a point here</translation>
        </message>
        <message>
            <location filename="../ui/point_editor.cpp" line="218" />
            <source>Snap to grid</source>
            <translation>Snap to grid</translation>
        </message>
        <message>
            <location filename="../ui/point_editor.cpp" line="222" />
            <source>Fit view</source>
            <translation>Fit view</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::PointTable</name>
        <message>
            <source>Points</source>
            <translation>Points</translation>
        </message>
        <message>
            <location filename="../ui/point_table.cpp" line="51" />
            <source>x</source>
            <translation>x</translation>
        </message>
        <message>
            <location filename="../ui/point_table.cpp" line="51" />
            <source>y</source>
            <translation>y</translation>
        </message>
        <message>
            <location filename="../ui/point_table.cpp" line="52" />
            <source>The points as numbers: type a decimal or a fraction such as 1/3.</source>
            <translation>The points as numbers: type a decimal or a fraction such as 1/3.</translation>
        </message>
        <message>
            <location filename="../ui/point_table.cpp" line="93" />
            <source>“%1” is not a number: type a decimal (2.5) or a fraction (5/2).</source>
            <translation>“%1” is not a number: type a decimal (2.5) or a fraction (5/2).</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::WorkPrecision</name>
        <message>
            <source>points of the polyline (evaluations of the curve)</source>
            <translation>points of the polyline (evaluations of the curve)</translation>
        </message>
        <message>
            <source>uniform t per segment</source>
            <translation>uniform t per segment</translation>
        </message>
        <message>
            <source>The same number of points on every segment wastes them on the short, gentle ones; adaptive subdivision of each segment puts them where the curve bends and needs fewer for the same error. Both errors fall like 1/N².</source>
            <translation>The same number of points on every segment wastes them on the short, gentle ones; adaptive subdivision of each segment puts them where the curve bends and needs fewer for the same error. Both errors fall like 1/N².</translation>
        </message>
        <message>
            <source>Against the number of points, both errors fall like 1/N² (twice the points, a quarter of the error), and adaptive subdivision, which puts its points where the curve bends, needs fewer for the same error. Its run time per point is higher: each point costs a flatness test.</source>
            <translation>Against the number of points, both errors fall like 1/N² (twice the points, a quarter of the error), and adaptive subdivision, which puts its points where the curve bends, needs fewer for the same error. Its run time per point is higher: each point costs a flatness test.</translation>
        </message>
        <message>
            <source>Catmull-Rom sampling: polyline against curve</source>
            <translation>Catmull-Rom sampling: polyline against curve</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="28" />
            <source>Curve sampling: polyline against curve</source>
            <translation>Curve sampling: polyline against curve</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="30" />
            <source>Evaluating a Bézier curve of degree n</source>
            <translation>Evaluating a Bézier curve of degree n</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="32" />
            <source>Least-squares Bézier fit: normal equations, QR, SVD</source>
            <translation>Least-squares Bézier fit: normal equations, QR, SVD</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="34" />
            <source>Integrators: global error against run time</source>
            <translation>Integrators: global error against run time</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="36" />
            <source>Soft body: constraint error against substeps</source>
            <translation>Soft body: constraint error against substeps</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="46" />
            <source>De Casteljau and the Bernstein sum stay at rounding level at every degree; Horner on the power basis loses digits as the degree grows, because its coefficients are huge alternating sums that cancel.</source>
            <translation>De Casteljau and the Bernstein sum stay at rounding level at every degree; Horner on the power basis loses digits as the degree grows, because its coefficients are huge alternating sums that cancel.</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="50" />
            <source>The normal equations square the condition number of M: near degree 25 they have lost almost every digit and by degree 30 the curve is wrong, while QR and SVD still hold about seven digits.</source>
            <translation>The normal equations square the condition number of M: near degree 25 they have lost almost every digit and by degree 30 the curve is wrong, while QR and SVD still hold about seven digits.</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="54" />
            <source>Halving h halves Euler's error but quarters Verlet's (order 1 against 2): at equal run time Verlet is orders of magnitude more accurate. RK4 (order 4) costs four evaluations per step and wins when high accuracy is needed.</source>
            <translation>Halving h halves Euler's error but quarters Verlet's (order 1 against 2): at equal run time Verlet is orders of magnitude more accurate. RK4 (order 4) costs four evaluations per step and wins when high accuracy is needed.</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="58" />
            <source>XPBD's constraint error falls as the substeps grow, at a cost proportional to their number; the seed's per-step corrections leave a lasting area deficit.</source>
            <translation>XPBD's constraint error falls as the substeps grow, at a cost proportional to their number; the seed's per-step corrections leave a lasting area deficit.</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="66" />
            <source>uniform</source>
            <translation>uniform</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="67" />
            <source>adaptive</source>
            <translation>adaptive</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="68" />
            <source>De Casteljau</source>
            <translation>De Casteljau</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="69" />
            <source>Bernstein sum</source>
            <translation>Bernstein sum</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="70" />
            <source>Horner (power basis)</source>
            <translation>Horner (power basis)</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="71" />
            <source>normal equations</source>
            <translation>normal equations</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="72" />
            <source>QR</source>
            <translation>QR</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="73" />
            <source>SVD</source>
            <translation>SVD</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="74" />
            <source>explicit Euler</source>
            <translation>explicit Euler</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="75" />
            <source>semi-implicit Euler</source>
            <translation>semi-implicit Euler</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="76" />
            <source>Verlet</source>
            <translation>Verlet</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="77" />
            <source>RK4</source>
            <translation>RK4</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="78" />
            <source>XPBD area</source>
            <translation>XPBD area</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="79" />
            <source>XPBD edge lengths</source>
            <translation>XPBD edge lengths</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="80" />
            <source>seed area (Annex II)</source>
            <translation>seed area (Annex II)</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="91" />
            <source>points</source>
            <translation>points</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="93" />
            <source>degree</source>
            <translation>degree</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="95" />
            <source>step h</source>
            <translation>step h</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="97" />
            <source>substeps</source>
            <translation>substeps</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="104" />
            <source>max distance between curve and polyline</source>
            <translation>max distance between curve and polyline</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="106" />
            <source>max |c(t) − exact| / max |Pᵢ|</source>
            <translation>max |c(t) − exact| / max |Pᵢ|</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="108" />
            <source>max |Pⱼ − Pⱼ(true)| / max |Pⱼ(true)|</source>
            <translation>max |Pⱼ − Pⱼ(true)| / max |Pⱼ(true)|</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="110" />
            <source>|x(T) − exact| at T = 10</source>
            <translation>|x(T) − exact| at T = 10</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="112" />
            <source>RMS relative constraint violation</source>
            <translation>RMS relative constraint violation</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="132" />
            <source>run time per call (s)</source>
            <translation>run time per call (s)</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="1" />
            <source>Arc length: Gauss–Legendre, Simpson, polyline</source>
            <translation>Arc length: Gauss–Legendre, Simpson, polyline</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="1" />
            <source>The adaptive rule, split at the cusp, reaches rounding level in about two microseconds; one 24-point Gauss rule is off by 1e-3 on the cusp and, repeated on pieces that do not end there, gains only a factor 4 per doubling (the kink, not the rule, sets the pace); Simpson gains 16 per halving, the polyline 4.</source>
            <translation>The adaptive rule, split at the cusp, reaches rounding level in about two microseconds; one 24-point Gauss rule is off by 1e-3 on the cusp and, repeated on pieces that do not end there, gains only a factor 4 per doubling (the kink, not the rule, sets the pace); Simpson gains 16 per halving, the polyline 4.</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="1" />
            <source>adaptive Gauss–Legendre</source>
            <translation>adaptive Gauss–Legendre</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="1" />
            <source>Gauss–Legendre 24 points</source>
            <translation>Gauss–Legendre 24 points</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="1" />
            <source>Simpson</source>
            <translation>Simpson</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="1" />
            <source>polyline</source>
            <translation>polyline</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="1" />
            <source>setting (tolerance, pieces, intervals or segments)</source>
            <translation>setting (tolerance, pieces, intervals or segments)</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="1" />
            <source>max relative error of L over four curves, one with a cusp</source>
            <translation>max relative error of L over four curves, one with a cusp</translation>
        </message>
        <message>
            <source>Energy drift: E/E₀ − 1 over 10⁵ steps of x″ = −x</source>
            <translation>Energy drift: E/E₀ − 1 over 10⁵ steps of x″ = −x</translation>
        </message>
        <message>
            <source>Explicit Euler multiplies the energy by 1 + h² every step: it grows without bound (×2·10⁴ after 10³ steps). RK4 loses the same tiny fraction every step (1.4·10⁻⁸ at h = 0.1), a drift that grows linearly (−1.39·10⁻³ after 10⁵ steps). Semi-implicit Euler and Verlet are symplectic: each keeps a modified energy exactly (x² + v² − h x v; v² + (1 − h²/4) x²), so their error stays bounded however long the run, about h/2 and h²/4.</source>
            <translation>Explicit Euler multiplies the energy by 1 + h² every step: it grows without bound (×2·10⁴ after 10³ steps). RK4 loses the same tiny fraction every step (1.4·10⁻⁸ at h = 0.1), a drift that grows linearly (−1.39·10⁻³ after 10⁵ steps). Semi-implicit Euler and Verlet are symplectic: each keeps a modified energy exactly (x² + v² − h x v; v² + (1 − h²/4) x²), so their error stays bounded however long the run, about h/2 and h²/4.</translation>
        </message>
        <message>
            <source>Verlet (Annex II start)</source>
            <translation>Verlet (Annex II start)</translation>
        </message>
        <message>
            <source>step n</source>
            <translation>step n</translation>
        </message>
        <message>
            <source>|E/E₀ − 1|, E = (v² + x²)/2</source>
            <translation>|E/E₀ − 1|, E = (v² + x²)/2</translation>
        </message>
        <message>
            <source>Bézier extraction + De Casteljau</source>
            <translation>Bézier extraction + De Casteljau</translation>
        </message>
        <message>
            <source>Evaluating a B-spline curve of degree p</source>
            <translation>Evaluating a B-spline curve of degree p</translation>
        </message>
        <message>
            <source>basis functions × points</source>
            <translation>basis functions × points</translation>
        </message>
        <message>
            <source>de Boor</source>
            <translation>de Boor</translation>
        </message>
        <message>
            <source>de Boor&apos;s algorithm, the Bézier segments with De Casteljau and the basis functions times the points all stay at rounding level at every degree: each is a chain of convex combinations. The Bézier segments, extracted once, are the quickest per point (one ratio t instead of p(p + 1)/2 ratios of knots) but carry the rounding of their extraction, up to a few times de Boor&apos;s error; the basis sum is the slowest.</source>
            <translation>de Boor&apos;s algorithm, the Bézier segments with De Casteljau and the basis functions times the points all stay at rounding level at every degree: each is a chain of convex combinations. The Bézier segments, extracted once, are the quickest per point (one ratio t instead of p(p + 1)/2 ratios of knots) but carry the rounding of their extraction, up to a few times de Boor&apos;s error; the basis sum is the slowest.</translation>
        </message>
        <message>
            <source>max |c(u) − exact| / max |Pᵢ|</source>
            <translation>max |c(u) − exact| / max |Pᵢ|</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::WorkPrecisionPanel</name>
        <message>
            <source>Work-precision plot: each marker is one setting of a method; lower is more accurate, left is cheaper (faster, or fewer points).</source>
            <translation>Work-precision plot: each marker is one setting of a method; lower is more accurate, left is cheaper (faster, or fewer points).</translation>
        </message>
        <message>
            <source>Press Measure: each method runs over a range of its setting, and the plot shows its error against its run time or against the setting itself (lower left is better).</source>
            <translation>Press Measure: each method runs over a range of its setting, and the plot shows its error against its run time or against the setting itself (lower left is better).</translation>
        </message>
        <message>
            <source>The x axis: the run time per call, or the method's setting itself (the number of points, the degree, the step…), which counts the cost without the clock.</source>
            <translation>The x axis: the run time per call, or the method's setting itself (the number of points, the degree, the step…), which counts the cost without the clock.</translation>
        </message>
        <message>
            <source>against the setting</source>
            <translation>against the setting</translation>
        </message>
        <message>
            <source>against %1</source>
            <translation>against %1</translation>
        </message>
        <message>
            <source>against run time</source>
            <translation>against run time</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_panel.cpp" line="120" />
            <source>Cancelled. Press Measure to start again.</source>
            <translation>Cancelled. Press Measure to start again.</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_panel.cpp" line="142" />
            <source>Which numerical method to measure: its error against its run time.</source>
            <translation>Which numerical method to measure: its error against its run time.</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_panel.cpp" line="143" />
            <source>Measure</source>
            <translation>Measure</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_panel.cpp" line="144" />
            <source>Run every method over a range of its setting and plot error against run time.</source>
            <translation>Run every method over a range of its setting and plot error against run time.</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_panel.cpp" line="145" />
            <source>Cancel</source>
            <translation>Cancel</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_panel.cpp" line="146" />
            <source>Stop the measurement.</source>
            <translation>Stop the measurement.</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_panel.cpp" line="147" />
            <source>Measuring…</source>
            <translation>Measuring…</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::UserFile</name>
        <message>
            <source>it cannot be read.</source>
            <translation>it cannot be read.</translation>
        </message>
        <message>
            <source>Cannot open “%1”: %2</source>
            <translation>Cannot open “%1”: %2</translation>
        </message>
        <message>
            <source>“%1” is a folder, not a file.</source>
            <translation>“%1” is a folder, not a file.</translation>
        </message>
        <message>
            <source>“%1” is larger than %2 MB, the most Granota reads from one file.</source>
            <translation>“%1” is larger than %2 MB, the most Granota reads from one file.</translation>
        </message>
        <message>
            <source>there is no space left on the disk</source>
            <translation>there is no space left on the disk</translation>
        </message>
        <message>
            <source>your disk quota is full</source>
            <translation>your disk quota is full</translation>
        </message>
        <message>
            <source>the disk is read-only</source>
            <translation>the disk is read-only</translation>
        </message>
        <message>
            <source>you do not have permission</source>
            <translation>you do not have permission</translation>
        </message>
        <message>
            <source>it does not exist</source>
            <translation>it does not exist</translation>
        </message>
        <message>
            <source>a folder on its path does not exist</source>
            <translation>a folder on its path does not exist</translation>
        </message>
        <message>
            <source>it is a folder</source>
            <translation>it is a folder</translation>
        </message>
        <message>
            <source>the name is too long</source>
            <translation>the name is too long</translation>
        </message>
        <message>
            <source>the file would be too large for the disk</source>
            <translation>the file would be too large for the disk</translation>
        </message>
        <message>
            <source>the disk reported an error</source>
            <translation>the disk reported an error</translation>
        </message>
        <message>
            <source>too many files are open</source>
            <translation>too many files are open</translation>
        </message>
        <message>
            <source>the file is in use</source>
            <translation>the file is in use</translation>
        </message>
        <message>
            <source>the system refused it (error %1)</source>
            <translation>the system refused it (error %1)</translation>
        </message>
        <message>
            <source>“%1” is a pipe or a device, not a file.</source>
            <translation>“%1” is a pipe or a device, not a file.</translation>
        </message>
        <message>
            <source>Cannot open “%1”: %2.</source>
            <translation>Cannot open “%1”: %2.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::Autosave</name>
        <message>
            <source>Cannot write the autosave “%1”: %2</source>
            <translation>Cannot write the autosave “%1”: %2</translation>
        </message>
        <message>
            <source>Cannot write the autosave “%1”: %2.</source>
            <translation>Cannot write the autosave “%1”: %2.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::CurveCanvas</name>
        <message>
            <source>These points are too large to draw: the canvas shows coordinates up to about ±%1. Their values are in the table; bring them closer to the origin to see the curve.</source>
            <translation>These points are too large to draw: the canvas shows coordinates up to about ±%1. Their values are in the table; bring them closer to the origin to see the curve.</translation>
        </message>
    </context>
    <context>
        <name>granota::CommandLine</name>
        <message>
            <source>bad body “%1” (1 … %2)</source>
            <translation>bad body “%1” (1 … %2)</translation>
        </message>
        <message>
            <source>--plot-body: the scene has no bodies to choose from (it needs two or more)</source>
            <translation>--plot-body: the scene has no bodies to choose from (it needs two or more)</translation>
        </message>
        <message>
            <source>Plot body K (1, 2, …) of the frog's scene alone, marked on the canvas.</source>
            <translation>Plot body K (1, 2, …) of the frog's scene alone, marked on the canvas.</translation>
        </message>
        <message>
            <source>bad size “%1” (WxH, e.g. 800x570)</source>
            <translation>bad size “%1” (WxH, e.g. 800x570)</translation>
        </message>
        <message>
            <source>Window size WxH (a screenshot's, else the window's), e.g. 800x570.</source>
            <translation>Window size WxH (a screenshot's, else the window's), e.g. 800x570.</translation>
        </message>
        <message>
            <source>cannot write “%1”</source>
            <translation>cannot write “%1”</translation>
        </message>
        <message>
            <source>unknown tab “%1” (decasteljau, bernstein, fit, catmull-rom, frog, bspline)</source>
            <translation>unknown tab “%1” (decasteljau, bernstein, fit, catmull-rom, frog, bspline)</translation>
        </message>
        <message>
            <source>unknown example “%1” (2.1 … 2.13)</source>
            <translation>unknown example “%1” (2.1 … 2.13)</translation>
        </message>
        <message>
            <source>cannot make a scratch folder for the screenshot run</source>
            <translation>cannot make a scratch folder for the screenshot run</translation>
        </message>
        <message>
            <source>unknown language “%1” (ca, en)</source>
            <translation>unknown language “%1” (ca, en)</translation>
        </message>
        <message>
            <source>A .granota document to open.</source>
            <translation>A .granota document to open.</translation>
        </message>
        <message>
            <source>Render the window (1280x800) to FILE.png and exit.</source>
            <translation>Render the window (1280x800) to FILE.png and exit.</translation>
        </message>
        <message>
            <source>Start in presentation mode.</source>
            <translation>Start in presentation mode.</translation>
        </message>
        <message>
            <source>Open the frog tab on scene NAME.</source>
            <translation>Open the frog tab on scene NAME.</translation>
        </message>
        <message>
            <source>Load worked example ID (2.1 … 2.13).</source>
            <translation>Load worked example ID (2.1 … 2.13).</translation>
        </message>
        <message>
            <source>Interface language: ca or en.</source>
            <translation>Interface language: ca or en.</translation>
        </message>
        <message>
            <source>Open on tab KEY: decasteljau, bernstein, fit, catmull-rom, frog, bspline.</source>
            <translation>Open on tab KEY: decasteljau, bernstein, fit, catmull-rom, frog, bspline.</translation>
        </message>
        <message>
            <source>Splines and soft bodies, for the classroom.</source>
            <translation>Splines and soft bodies, for the classroom.</translation>
        </message>
        <message>
            <source>List the thesis&apos;s figures: number, variants, caption; and exit.</source>
            <translation>List the thesis&apos;s figures: number, variants, caption; and exit.</translation>
        </message>
        <message>
            <source>Draw the thesis&apos;s figure N (2.1 … 4.13), with --export.</source>
            <translation>Draw the thesis&apos;s figure N (2.1 … 4.13), with --export.</translation>
        </message>
        <message>
            <source>The figure&apos;s variant V (--list-figures names them).</source>
            <translation>The figure&apos;s variant V (--list-figures names them).</translation>
        </message>
        <message>
            <source>Write the figure&apos;s view alone to FILE (.svg, .pdf, .png, .tex or .csv) and exit.</source>
            <translation>Write the figure&apos;s view alone to FILE (.svg, .pdf, .png, .tex or .csv) and exit.</translation>
        </message>
        <message>
            <source>Resolution of a PNG export, 24 … 1200 (96: one pixel per pixel).</source>
            <translation>Resolution of a PNG export, 24 … 1200 (96: one pixel per pixel).</translation>
        </message>
        <message>
            <source>--figure N and --export FILE go together (--variant and --dpi with them)</source>
            <translation>--figure N and --export FILE go together (--variant and --dpi with them)</translation>
        </message>
        <message>
            <source>unknown figure “%1” (2.1 … 2.10, 4.1 … 4.13; --list-figures)</source>
            <translation>unknown figure “%1” (2.1 … 2.10, 4.1 … 4.13; --list-figures)</translation>
        </message>
        <message>
            <source>Fig %1 has no variant “%2” (%3)</source>
            <translation>Fig %1 has no variant “%2” (%3)</translation>
        </message>
        <message>
            <source>cannot tell the format of “%1”: end it in .svg, .pdf, .png, .tex or .csv</source>
            <translation>cannot tell the format of “%1”: end it in .svg, .pdf, .png, .tex or .csv</translation>
        </message>
        <message>
            <source>bad resolution “%1” (24 … 1200)</source>
            <translation>bad resolution “%1” (24 … 1200)</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::CurveTab</name>
        <message>
            <source>“pointLabels” is not true or false.</source>
            <translation>“pointLabels” is not true or false.</translation>
        </message>
        <message>
            <source>Keys: ] and [ select a point, the arrows nudge it (Shift: ten times more), Delete removes it; Tab leaves the canvas.</source>
            <translation>Keys: ] and [ select a point, the arrows nudge it (Shift: ten times more), Delete removes it; Tab leaves the canvas.</translation>
        </message>
        <message>
            <source>“exactPoints” is not a list of [x, y] pairs, one for each point.</source>
            <translation>“exactPoints” is not a list of [x, y] pairs, one for each point.</translation>
        </message>
        <message>
            <source>“exactPoints” entry %1 is not a pair of exact values of point %1 (fractions such as “1/3”, or null).</source>
            <translation>“exactPoints” entry %1 is not a pair of exact values of point %1 (fractions such as “1/3”, or null).</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::TikzOptionsDialog</name>
        <message>
            <source>The defaults fit a beamer frame; the picture needs \usepackage{tikz}.</source>
            <translation>The defaults fit a beamer frame; the picture needs \usepackage{tikz}.</translation>
        </message>
        <message>
            <source>Height at most:</source>
            <translation>Height at most:</translation>
        </message>
        <message>
            <source>Width:</source>
            <translation>Width:</translation>
        </message>
        <message>
            <source>Grid</source>
            <translation>Grid</translation>
        </message>
        <message>
            <source>Axes with tick labels</source>
            <translation>Axes with tick labels</translation>
        </message>
        <message>
            <source>Height at most</source>
            <translation>Height at most</translation>
        </message>
        <message>
            <source>A taller picture is made smaller until it is this tall. %1 cm fits a beamer frame with a title.</source>
            <translation>A taller picture is made smaller until it is this tall. %1 cm fits a beamer frame with a title.</translation>
        </message>
        <message>
            <source>Width</source>
            <translation>Width</translation>
        </message>
        <message>
            <source>The picture's width on the page, labels included. %1 cm fits a beamer frame.</source>
            <translation>The picture's width on the page, labels included. %1 cm fits a beamer frame.</translation>
        </message>
        <message>
            <source>TikZ picture</source>
            <translation>TikZ picture</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::ShortcutsHelp</name>
        <message>
            <source>Frog tab (P, S, the comma and the period, R, M, [ and ] whenever the tab is shown, unless a field is being typed in)</source>
            <translation>Frog tab (P, S, the comma and the period, R, M, [ and ] whenever the tab is shown, unless a field is being typed in)</translation>
        </message>
        <message>
            <source>Stopwatch: mark the step shown, or clear the mark</source>
            <translation>Stopwatch: mark the step shown, or clear the mark</translation>
        </message>
        <message>
            <source>M</source>
            <translation>M</translation>
        </message>
        <message>
            <source>One step back in the recorded run (pausing first)</source>
            <translation>One step back in the recorded run (pausing first)</translation>
        </message>
        <message>
            <source>,</source>
            <translation>,</translation>
        </message>
        <message>
            <source>Slower and faster (⅛× to 4×)</source>
            <translation>Slower and faster (⅛× to 4×)</translation>
        </message>
        <message>
            <source>[ and ]</source>
            <translation>[ and ]</translation>
        </message>
        <message>
            <source>Alt+arrows (Shift: ten times more)</source>
            <translation>Alt+arrows (Shift: ten times more)</translation>
        </message>
        <message>
            <source>De Casteljau: mold the curve at t, c(t) moving by the same step</source>
            <translation>De Casteljau: mold the curve at t, c(t) moving by the same step</translation>
        </message>
        <message>
            <source>De Casteljau, Fitting and Catmull-Rom canvases</source>
            <translation>De Casteljau, Fitting and Catmull-Rom canvases</translation>
        </message>
        <message>
            <source>The window</source>
            <translation>The window</translation>
        </message>
        <message>
            <source>On the canvas: a new body at the cursor, held until released</source>
            <translation>On the canvas: a new body at the cursor, held until released</translation>
        </message>
        <message>
            <source>Space</source>
            <translation>Space</translation>
        </message>
        <message>
            <source>On the canvas: let go, or clear the ruler</source>
            <translation>On the canvas: let go, or clear the ruler</translation>
        </message>
        <message>
            <source>Esc</source>
            <translation>Esc</translation>
        </message>
        <message>
            <source>On the canvas: grab the body at the cursor (or the nearest one), again to let go</source>
            <translation>On the canvas: grab the body at the cursor (or the nearest one), again to let go</translation>
        </message>
        <message>
            <source>G or Enter</source>
            <translation>G or Enter</translation>
        </message>
        <message>
            <source>On the canvas: move the keyboard cursor, and what it holds</source>
            <translation>On the canvas: move the keyboard cursor, and what it holds</translation>
        </message>
        <message>
            <source>Arrows (Shift: five times further)</source>
            <translation>Arrows (Shift: five times further)</translation>
        </message>
        <message>
            <source>Reset the scene</source>
            <translation>Reset the scene</translation>
        </message>
        <message>
            <source>R</source>
            <translation>R</translation>
        </message>
        <message>
            <source>One step (pausing first)</source>
            <translation>One step (pausing first)</translation>
        </message>
        <message>
            <source>S or .</source>
            <translation>S or .</translation>
        </message>
        <message>
            <source>Pause and run</source>
            <translation>Pause and run</translation>
        </message>
        <message>
            <source>P</source>
            <translation>P</translation>
        </message>
        <message>
            <source>Remove the selected point</source>
            <translation>Remove the selected point</translation>
        </message>
        <message>
            <source>Delete, Backspace</source>
            <translation>Delete, Backspace</translation>
        </message>
        <message>
            <source>Nudge the selected point by a round step</source>
            <translation>Nudge the selected point by a round step</translation>
        </message>
        <message>
            <source>Arrows (Shift: ten times more)</source>
            <translation>Arrows (Shift: ten times more)</translation>
        </message>
        <message>
            <source>Select the next or the previous point</source>
            <translation>Select the next or the previous point</translation>
        </message>
        <message>
            <source>] and [</source>
            <translation>] and [</translation>
        </message>
        <message>
            <source>Move the focus into and out of the canvas, to the next or previous control</source>
            <translation>Move the focus into and out of the canvas, to the next or previous control</translation>
        </message>
        <message>
            <source>Tab, Shift+Tab</source>
            <translation>Tab, Shift+Tab</translation>
        </message>
        <message>
            <source>, </source>
            <translation>, </translation>
        </message>
        <message>
            <source>L</source>
            <translation>L</translation>
        </message>
        <message>
            <source>On the canvas: a ruler from the cursor; move it with the arrows, L again to fix it</source>
            <translation>On the canvas: a ruler from the cursor; move it with the arrows, L again to fix it</translation>
        </message>
        <message>
            <source>Right drag, or Ctrl+drag</source>
            <translation>Right drag, or Ctrl+drag</translation>
        </message>
        <message>
            <source>On the canvas: measure in px with the ruler</source>
            <translation>On the canvas: measure in px with the ruler</translation>
        </message>
        <message>
            <source>Catmull-Rom, Hermite family: move the selected point&apos;s tangent by 1/10</source>
            <translation>Catmull-Rom, Hermite family: move the selected point&apos;s tangent by 1/10</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::ExactPanel</name>
        <message>
            <source>Exact computation</source>
            <translation>Exact computation</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::DeCasteljauCurveDrag</name>
        <message>
            <source>Refused: a coordinate must be a finite number.</source>
            <translation>Refused: a coordinate must be a finite number.</translation>
        </message>
        <message>
            <source>c(t) at t = %1 moved by %2: the control points changed the least that does it.</source>
            <translation>c(t) at t = %1 moved by %2: the control points changed the least that does it.</translation>
        </message>
        <message>
            <source>Mold the curve at t = %1</source>
            <translation>Mold the curve at t = %1</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::CurvatureCombScaleBox</name>
        <message>
            <source>automatic</source>
            <translation>automatic</translation>
        </message>
        <message>
            <source>The comb's scale: a tooth is |κ| × this long (in the curve's units). Automatic: the 90th percentile of |κ| gives teeth 15 % of the control polygon's size, and the teeth rescale as the curve changes; a number keeps them comparable. 0 is automatic.</source>
            <translation>The comb's scale: a tooth is |κ| × this long (in the curve's units). Automatic: the 90th percentile of |κ| gives teeth 15 % of the control polygon's size, and the teeth rescale as the curve changes; a number keeps them comparable. 0 is automatic.</translation>
        </message>
        <message>
            <source>Comb scale</source>
            <translation>Comb scale</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::FrogPlotPanel</name>
        <message>
            <source>Whose values to plot: all the bodies summed (the area error: their mean; the stretch: the largest), or one body alone, with the legs that hang from it. The canvas marks the body chosen. The CSV holds what is plotted.</source>
            <translation>Whose values to plot: all the bodies summed (the area error: their mean; the stretch: the largest), or one body alone, with the legs that hang from it. The canvas marks the body chosen. The CSV holds what is plotted.</translation>
        </message>
        <message>
            <source>Body %1 alone: its values are kept from the next step on.</source>
            <translation>Body %1 alone: its values are kept from the next step on.</translation>
        </message>
        <message>
            <source>Body %1 alone: its values are kept from %2 s on.</source>
            <translation>Body %1 alone: its values are kept from %2 s on.</translation>
        </message>
        <message>
            <source>Body %1</source>
            <translation>Body %1</translation>
        </message>
        <message>
            <source>All bodies</source>
            <translation>All bodies</translation>
        </message>
        <message>
            <source>|L/L₀ − 1|</source>
            <translation>|L/L₀ − 1|</translation>
        </message>
        <message>
            <source>total</source>
            <translation>total</translation>
        </message>
        <message>
            <source>time (s)</source>
            <translation>time (s)</translation>
        </message>
        <message>
            <source>damping</source>
            <translation>damping</translation>
        </message>
        <message>
            <source>other losses</source>
            <translation>other losses</translation>
        </message>
        <message>
            <source>link %1</source>
            <translation>link %1</translation>
        </message>
        <message>
            <source>largest stretch</source>
            <translation>largest stretch</translation>
        </message>
        <message>
            <source>kinetic</source>
            <translation>kinetic</translation>
        </message>
        <message>
            <source>gravitational</source>
            <translation>gravitational</translation>
        </message>
        <message>
            <source>elastic</source>
            <translation>elastic</translation>
        </message>
        <message>
            <source>dθ/dt (rad/step)</source>
            <translation>dθ/dt (rad/step)</translation>
        </message>
        <message>
            <source>contacts</source>
            <translation>contacts</translation>
        </message>
        <message>
            <source>area error</source>
            <translation>area error</translation>
        </message>
        <message>
            <source>area error (%)</source>
            <translation>area error (%)</translation>
        </message>
        <message>
            <source>angle θ from the vertical (rad)</source>
            <translation>angle θ from the vertical (rad)</translation>
        </message>
        <message>
            <source>What to plot against time: the energies and what damping and the rest took, the area error, the largest stretch, the contacts; or, for the pendulums, each link's angle against its angular velocity. The wheel zooms the window of seconds.</source>
            <translation>What to plot against time: the energies and what damping and the rest took, the area error, the largest stretch, the contacts; or, for the pendulums, each link's angle against its angular velocity. The wheel zooms the window of seconds.</translation>
        </message>
        <message>
            <source>Energies in px²/step², unit masses. The seed's springs and area are corrections, not forces: it stores no elastic energy and books no losses; total = kinetic + gravitational.</source>
            <translation>Energies in px²/step², unit masses. The seed's springs and area are corrections, not forces: it stores no elastic energy and books no losses; total = kinetic + gravitational.</translation>
        </message>
        <message>
            <source>Plots over time</source>
            <translation>Plots over time</translation>
        </message>
        <message>
            <source>Phase plot of the last %1 s: each link's orbit; a small swing of a free link is an ellipse, with the period 2π√(L/g).</source>
            <translation>Phase plot of the last %1 s: each link's orbit; a small swing of a free link is an ellipse, with the period 2π√(L/g).</translation>
        </message>
        <message>
            <source>Phase plot of the last %1 s: each link's orbit. The dashed lines are the first link's limits (§4.15): an orbit that reaches one is cut off.</source>
            <translation>Phase plot of the last %1 s: each link's orbit. The dashed lines are the first link's limits (§4.15): an orbit that reaches one is cut off.</translation>
        </message>
        <message>
            <source>Phase plot (pendulums)</source>
            <translation>Phase plot (pendulums)</translation>
        </message>
        <message>
            <source>Energies in mass·px²/step². Other losses: hits and friction at walls and between bodies, and the solver's own dissipation, less what the mouse put in.</source>
            <translation>Energies in mass·px²/step². Other losses: hits and friction at walls and between bodies, and the solver's own dissipation, less what the mouse put in.</translation>
        </message>
        <message>
            <source>Largest stretch</source>
            <translation>Largest stretch</translation>
        </message>
        <message>
            <source>Exported %1</source>
            <translation>Exported %1</translation>
        </message>
        <message>
            <source>Export the series</source>
            <translation>Export the series</translation>
        </message>
        <message>
            <source>Export CSV…</source>
            <translation>Export CSV…</translation>
        </message>
        <message>
            <source>Every step kept (the last %1 minutes), in the columns of granota-cli simulate --series.</source>
            <translation>Every step kept (the last %1 minutes), in the columns of granota-cli simulate --series.</translation>
        </message>
        <message>
            <source>Energy</source>
            <translation>Energy</translation>
        </message>
        <message>
            <source>energy</source>
            <translation>energy</translation>
        </message>
        <message>
            <source>Contacts</source>
            <translation>Contacts</translation>
        </message>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>CSV files (*.csv)</translation>
        </message>
        <message>
            <source>Area error</source>
            <translation>Area error</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::ThesisFigures</name>
        <message>
            <source>Fig %1 — %2</source>
            <translation>Fig %1 — %2</translation>
        </message>
        <message>
            <source>Fig %1</source>
            <translation>Fig %1</translation>
        </message>
        <message>
            <source>Fig %1 names no tab of Granota.</source>
            <translation>Fig %1 names no tab of Granota.</translation>
        </message>
        <message>
            <source>Fig %1 could not be shown.</source>
            <translation>Fig %1 could not be shown.</translation>
        </message>
        <message>
            <source>Fig %1 could not be shown: %2</source>
            <translation>Fig %1 could not be shown: %2</translation>
        </message>
        <message>
            <source>Unknown export format “%1” (svg, pdf, png, tex, csv).</source>
            <translation>Unknown export format “%1” (svg, pdf, png, tex, csv).</translation>
        </message>
        <message>
            <source>as defined</source>
            <translation>as defined</translation>
        </message>
        <message>
            <source>as the thesis computed it</source>
            <translation>as the thesis computed it</translation>
        </message>
        <message>
            <source>every degree</source>
            <translation>every degree</translation>
        </message>
        <message>
            <source>(a) at rest</source>
            <translation>(a) at rest</translation>
        </message>
        <message>
            <source>(b) grabbed</source>
            <translation>(b) grabbed</translation>
        </message>
        <message>
            <source>degree n = %1</source>
            <translation>degree n = %1</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::ThesisFiguresDialog</name>
        <message numerus="yes">
            <source>Showing Fig %1 replaces the Frog tab&apos;s run of %n step(s), which cannot be undone. Show it?</source>
            <translation>
                <numerusform>Showing Fig %1 replaces the Frog tab&apos;s run of %n step, which cannot be undone. Show it?</numerusform>
                <numerusform>Showing Fig %1 replaces the Frog tab&apos;s run of %n steps, which cannot be undone. Show it?</numerusform>
            </translation>
        </message>
        <message>
            <source>Thesis figures</source>
            <translation>Thesis figures</translation>
        </message>
        <message>
            <source>&amp;Variant:</source>
            <translation>&amp;Variant:</translation>
        </message>
        <message>
            <source>&amp;Show</source>
            <translation>&amp;Show</translation>
        </message>
        <message>
            <source>&amp;Export…</source>
            <translation>&amp;Export…</translation>
        </message>
        <message>
            <source>Close</source>
            <translation>Close</translation>
        </message>
        <message>
            <source>It has no tab of its own: Export… writes it.</source>
            <translation>It has no tab of its own: Export… writes it.</translation>
        </message>
        <message>
            <source>Export figure</source>
            <translation>Export figure</translation>
        </message>
        <message>
            <source>Figures (*.svg *.pdf *.png *.tex *.csv)</source>
            <translation>Figures (*.svg *.pdf *.png *.tex *.csv)</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::ErrorText</name>
        <message>
            <source>point %1 is %2, not two numbers: write “x,y” with decimal points, “x;y” with decimal commas (as a spreadsheet in Catalan saves it), or x and y separated by a tab; one point a line.</source>
            <translation>point %1 is %2, not two numbers: write “x,y” with decimal points, “x;y” with decimal commas (as a spreadsheet in Catalan saves it), or x and y separated by a tab; one point a line.</translation>
        </message>
        <message>
            <source>point %1: %2 is %3 characters long, more than %4, the longest number Granota reads.</source>
            <translation>point %1: %2 is %3 characters long, more than %4, the longest number Granota reads.</translation>
        </message>
        <message>
            <source>point %1: %2 = %3 is not a number (write integers, decimals or fractions p/q).</source>
            <translation>point %1: %2 = %3 is not a number (write integers, decimals or fractions p/q).</translation>
        </message>
        <message>
            <source>point %1: %2 = %3 is too large (the largest double is about 1.8e308).</source>
            <translation>point %1: %2 = %3 is too large (the largest double is about 1.8e308).</translation>
        </message>
        <message>
            <source>point %1: %2 = %3 is too close to zero to read.</source>
            <translation>point %1: %2 = %3 is too close to zero to read.</translation>
        </message>
        <message>
            <source>No points were given.</source>
            <translation>No points were given.</translation>
        </message>
        <message>
            <source>The file holds no points.</source>
            <translation>The file holds no points.</translation>
        </message>
        <message>
            <source>There are more than %1 points, the most Granota reads.</source>
            <translation>There are more than %1 points, the most Granota reads.</translation>
        </message>
        <message>
            <source>The text is not a JSON list of points [[x,y],…].</source>
            <translation>The text is not a JSON list of points [[x,y],…].</translation>
        </message>
        <message>
            <source>The JSON text is %1, not a list of points [[x,y],…].</source>
            <translation>The JSON text is %1, not a list of points [[x,y],…].</translation>
        </message>
        <message>
            <source>JSON point %1 is %2, not a pair [x,y].</source>
            <translation>JSON point %1 is %2, not a pair [x,y].</translation>
        </message>
        <message>
            <source>The scene has no parameter %1.</source>
            <translation>The scene has no parameter %1.</translation>
        </message>
        <message>
            <source>“%1” must be a whole number.</source>
            <translation>“%1” must be a whole number.</translation>
        </message>
        <message>
            <source>“%1” must be from %2 to %3.</source>
            <translation>“%1” must be from %2 to %3.</translation>
        </message>
        <message>
            <source>“%1” must be a number.</source>
            <translation>“%1” must be a number.</translation>
        </message>
        <message>
            <source>“%1” must be a pair of numbers x, y.</source>
            <translation>“%1” must be a pair of numbers x, y.</translation>
        </message>
        <message>
            <source>“%1” must be a finite number.</source>
            <translation>“%1” must be a finite number.</translation>
        </message>
        <message>
            <source>“%1” must be a finite number ≥ 0.</source>
            <translation>“%1” must be a finite number ≥ 0.</translation>
        </message>
        <message>
            <source>“%1” must be at most 1e15 in magnitude.</source>
            <translation>“%1” must be at most 1e15 in magnitude.</translation>
        </message>
        <message>
            <source>A body needs at least 3 sides (a polygon), not %1.</source>
            <translation>A body needs at least 3 sides (a polygon), not %1.</translation>
        </message>
        <message>
            <source>A body has at most %2 sides, not %1.</source>
            <translation>A body has at most %2 sides, not %1.</translation>
        </message>
        <message>
            <source>The frame must be at least 1 × 1 px.</source>
            <translation>The frame must be at least 1 × 1 px.</translation>
        </message>
        <message>
            <source>Bodies × sides must be at most %1 vertices in all: lower the bodies or the sides.</source>
            <translation>Bodies × sides must be at most %1 vertices in all: lower the bodies or the sides.</translation>
        </message>
        <message>
            <source>A Bézier outline of degree %1 sampled at %2 points costs %3 interpolations, more than %4: lower the sides or the Bézier samples.</source>
            <translation>A Bézier outline of degree %1 sampled at %2 points costs %3 interpolations, more than %4: lower the sides or the Bézier samples.</translation>
        </message>
        <message>
            <source>%1 bodies of radius %2 px do not fit side by side in a %3 × %4 px frame, and piled up their %5 vertices would all touch (at most %6 may start piled): lower the bodies, the sides or the radius, or widen the frame.</source>
            <translation>%1 bodies of radius %2 px do not fit side by side in a %3 × %4 px frame, and piled up their %5 vertices would all touch (at most %6 may start piled): lower the bodies, the sides or the radius, or widen the frame.</translation>
        </message>
        <message>
            <source>The stable solver takes substeps from %1 to %2, an edge compliance from 0 to %3 and a damping ratio from 0 to %4.</source>
            <translation>The stable solver takes substeps from %1 to %2, an edge compliance from 0 to %3 and a damping ratio from 0 to %4.</translation>
        </message>
        <message>
            <source>There are too few points.</source>
            <translation>There are too few points.</translation>
        </message>
        <message>
            <source>A value is outside the range Granota accepts.</source>
            <translation>A value is outside the range Granota accepts.</translation>
        </message>
        <message>
            <source>The path is not a file.</source>
            <translation>The path is not a file.</translation>
        </message>
        <message>
            <source>The text is cut off before its end.</source>
            <translation>The text is cut off before its end.</translation>
        </message>
        <message>
            <source>The system refused to read or write the file.</source>
            <translation>The system refused to read or write the file.</translation>
        </message>
        <message>
            <source>A value is not written in a form Granota reads.</source>
            <translation>A value is not written in a form Granota reads.</translation>
        </message>
        <message>
            <source>Line %1: %2</source>
            <translation>Line %1: %2</translation>
        </message>
        <message>
            <source>The scene names a component %1 that does not exist (the components are %2).</source>
            <translation>The scene names a component %1 that does not exist (the components are %2).</translation>
        </message>
        <message>
            <source>The degree of a B-spline must be from 1 to %2, not %1.</source>
            <translation>The degree of a B-spline must be from 1 to %2, not %1.</translation>
        </message>
        <message>
            <source>A B-spline of degree %1 needs at least %2 control points, not %3.</source>
            <translation>A B-spline of degree %1 needs at least %2 control points, not %3.</translation>
        </message>
        <message>
            <source>A B-spline of degree %1 with %2 control points needs %3 knots, not %4.</source>
            <translation>A B-spline of degree %1 with %2 control points needs %3 knots, not %4.</translation>
        </message>
        <message>
            <source>A rational B-spline needs one weight per control point: %1 weights, not %2.</source>
            <translation>A rational B-spline needs one weight per control point: %1 weights, not %2.</translation>
        </message>
        <message>
            <source>%1 is not a finite number.</source>
            <translation>%1 is not a finite number.</translation>
        </message>
        <message>
            <source>The knots must not decrease: u_%1 = %2 is greater than u_%3 = %4.</source>
            <translation>The knots must not decrease: u_%1 = %2 is greater than u_%3 = %4.</translation>
        </message>
        <message>
            <source>The knot %1 is repeated %2 times; inside, a B-spline of degree %3 allows it at most %4 times.</source>
            <translation>The knot %1 is repeated %2 times; inside, a B-spline of degree %3 allows it at most %4 times.</translation>
        </message>
        <message>
            <source>The knot %1 is repeated %2 times; at an end, a B-spline of degree %3 allows it at most %4 times.</source>
            <translation>The knot %1 is repeated %2 times; at an end, a B-spline of degree %3 allows it at most %4 times.</translation>
        </message>
        <message>
            <source>The domain [%1, %2] of the B-spline is empty.</source>
            <translation>The domain [%1, %2] of the B-spline is empty.</translation>
        </message>
        <message>
            <source>The weight w_%1 = %2 must be positive.</source>
            <translation>The weight w_%1 = %2 must be positive.</translation>
        </message>
        <message>
            <source>A knot is inserted at least once, not %1 times.</source>
            <translation>A knot is inserted at least once, not %1 times.</translation>
        </message>
        <message>
            <source>The knot %1 is outside the domain [%2, %3].</source>
            <translation>The knot %1 is outside the domain [%2, %3].</translation>
        </message>
        <message>
            <source>The knot %1 already has multiplicity %2: inserting it %3 more times would exceed the degree %4.</source>
            <translation>The knot %1 already has multiplicity %2: inserting it %3 more times would exceed the degree %4.</translation>
        </message>
        <message>
            <source>This rational B-spline cannot float its ends: every choice of outer knots tried needs a weight that is not positive.</source>
            <translation>This rational B-spline cannot float its ends: every choice of outer knots tried needs a weight that is not positive.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::ShortcutsDialog</name>
        <message>
            <source>Keyboard shortcuts</source>
            <translation>Keyboard shortcuts</translation>
        </message>
        <message>
            <source>&amp;Close</source>
            <translation>&amp;Close</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::FieldInputFilter</name>
        <message>
            <source>%1 must be between %2 and %3.</source>
            <translation>%1 must be between %2 and %3.</translation>
        </message>
        <message>
            <source>%1 was not applied.</source>
            <translation>%1 was not applied.</translation>
        </message>
        <message>
            <source>The value must be between %1 and %2.</source>
            <translation>The value must be between %1 and %2.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::BSplineTab</name>
        <message>
            <source>%1 knots for %2 points of degree %3 (n + p + 2 = %4 are needed)</source>
            <translation>%1 knots for %2 points of degree %3 (n + p + 2 = %4 are needed)</translation>
        </message>
        <message>
            <source>%1 weights for %2 points</source>
            <translation>%1 weights for %2 points</translation>
        </message>
        <message numerus="yes">
            <source>%n weight(s) for %1 points: give one per point, or none.</source>
            <translation>
                <numerusform>%n weight for %1 points: give one per point, or none.</numerusform>
                <numerusform>%n weights for %1 points: give one per point, or none.</numerusform>
            </translation>
        </message>
        <message>
            <source>&amp;Degree p:</source>
            <translation>&amp;Degree p:</translation>
        </message>
        <message>
            <source>&amp;Elevate degree</source>
            <translation>&amp;Elevate degree</translation>
        </message>
        <message>
            <source>&amp;Insert knot at u</source>
            <translation>&amp;Insert knot at u</translation>
        </message>
        <message>
            <source>&amp;Knots:</source>
            <translation>&amp;Knots:</translation>
        </message>
        <message>
            <source>&amp;Remove knot</source>
            <translation>&amp;Remove knot</translation>
        </message>
        <message>
            <source>&amp;Weights:</source>
            <translation>&amp;Weights:</translation>
        </message>
        <message>
            <source>A B-spline here has at most %1 control points.</source>
            <translation>A B-spline here has at most %1 control points.</translation>
        </message>
        <message>
            <source>A B-spline needs between 2 and %1 control points; the file has %2.</source>
            <translation>A B-spline needs between 2 and %1 control points; the file has %2.</translation>
        </message>
        <message>
            <source>A B-spline of degree %1 needs at least %2 control points; there are %3.</source>
            <translation>A B-spline of degree %1 needs at least %2 control points; there are %3.</translation>
        </message>
        <message>
            <source>A knot can be repeated at most p = %1 times inside the domain and p + 1 times at an end, and the domain [uₚ, uₙ₊₁] cannot be empty.</source>
            <translation>A knot can be repeated at most p = %1 times inside the domain and p + 1 times at an end, and the domain [uₚ, uₙ₊₁] cannot be empty.</translation>
        </message>
        <message>
            <source>A knot is inserted inside the domain [%1, %2].</source>
            <translation>A knot is inserted inside the domain [%1, %2].</translation>
        </message>
        <message>
            <source>A point has no exact form (dragged freely): the net is shown in doubles.</source>
            <translation>A point has no exact form (dragged freely): the net is shown in doubles.</translation>
        </message>
        <message>
            <source>A weight must be positive, not %1.</source>
            <translation>A weight must be positive, not %1.</translation>
        </message>
        <message>
            <source>Actions</source>
            <translation>Actions</translation>
        </message>
        <message>
            <source>B-spline</source>
            <translation>B-spline</translation>
        </message>
        <message>
            <source>B-spline canvas</source>
            <translation>B-spline canvas</translation>
        </message>
        <message numerus="yes">
            <source>B-spline of degree %1 with %n control point(s) and %2 knots.</source>
            <translation>
                <numerusform>B-spline of degree %1 with %n control point and %2 knots.</numerusform>
                <numerusform>B-spline of degree %1 with %n control points and %2 knots.</numerusform>
            </translation>
        </message>
        <message>
            <source>B-splines</source>
            <translation>B-splines</translation>
        </message>
        <message>
            <source>Basis functions Nᵢ,ₚ(u) (Cox–de Boor)</source>
            <translation>Basis functions Nᵢ,ₚ(u) (Cox–de Boor)</translation>
        </message>
        <message>
            <source>Basis functions at u (degree p = %1)</source>
            <translation>Basis functions at u (degree p = %1)</translation>
        </message>
        <message>
            <source>Boehm&apos;s knot insertion: one more point and one more knot, the curve unchanged; the old polygon stays drawn dashed under the new one.</source>
            <translation>Boehm&apos;s knot insertion: one more point and one more knot, the curve unchanged; the old polygon stays drawn dashed under the new one.</translation>
        </message>
        <message>
            <source>Bé&amp;zier segments</source>
            <translation>Bé&amp;zier segments</translation>
        </message>
        <message>
            <source>Bézier (no interior knot)</source>
            <translation>Bézier (no interior knot)</translation>
        </message>
        <message>
            <source>C&amp;ubic Bézier circle beside</source>
            <translation>C&amp;ubic Bézier circle beside</translation>
        </message>
        <message>
            <source>Change the weights</source>
            <translation>Change the weights</translation>
        </message>
        <message>
            <source>Clamped: p + 1 equal knots at each end, the curve starts at P₀ and ends at Pₙ. Uniform: 0, 1, 2, …, the ends float. Bézier: no interior knot, degree n, exactly the Bézier curve of the points (Def 2.4). “Edited” is shown once a knot was moved or inserted.</source>
            <translation>Clamped: p + 1 equal knots at each end, the curve starts at P₀ and ends at Pₙ. Uniform: 0, 1, 2, …, the ends float. Bézier: no interior knot, degree n, exactly the Bézier curve of the points (Def 2.4). “Edited” is shown once a knot was moved or inserted.</translation>
        </message>
        <message>
            <source>Conic: a hyperbola (w = 2)</source>
            <translation>Conic: a hyperbola (w = 2)</translation>
        </message>
        <message>
            <source>Conic: a parabola (w = 1)</source>
            <translation>Conic: a parabola (w = 1)</translation>
        </message>
        <message>
            <source>Conic: an ellipse (w = 1/2)</source>
            <translation>Conic: an ellipse (w = 1/2)</translation>
        </message>
        <message>
            <source>Dashed red: the cubic Bézier quarter circle (1, 0), (1, k), (k, 1), (0, 1), k = 4(√2 − 1)/3 ≈ %1: its radius is off by up to %2; the rational quarter circle&apos;s by nothing (x² + y² = 1 exactly at every rational u).</source>
            <translation>Dashed red: the cubic Bézier quarter circle (1, 0), (1, k), (k, 1), (0, 1), k = 4(√2 − 1)/3 ≈ %1: its radius is off by up to %2; the rational quarter circle&apos;s by nothing (x² + y² = 1 exactly at every rational u).</translation>
        </message>
        <message>
            <source>Degree %1</source>
            <translation>Degree %1</translation>
        </message>
        <message>
            <source>Degree p + 1, the same curve: more points, each knot once more.</source>
            <translation>Degree p + 1, the same curve: more points, each knot once more.</translation>
        </message>
        <message>
            <source>Drag a point to move it; double-click to add one; Delete removes the selected point; drag the paper to pan, wheel to zoom. The ringed points are the p + 1 that act at u.</source>
            <translation>Drag a point to move it; double-click to add one; Delete removes the selected point; drag the paper to pan, wheel to zoom. The ringed points are the p + 1 that act at u.</translation>
        </message>
        <message>
            <source>Drag a point; drag a knot on the ruler, double-click it to insert one; move u to follow de Boor&apos;s construction.</source>
            <translation>Drag a point; drag a knot on the ruler, double-click it to insert one; move u to follow de Boor&apos;s construction.</translation>
        </message>
        <message>
            <source>Draw the control polygon of each Bézier segment of the curve (the knots inserted up to multiplicity p): one polynomial piece per span.</source>
            <translation>Draw the control polygon of each Bézier segment of the curve (the knots inserted up to multiplicity p): one polynomial piece per span.</translation>
        </message>
        <message>
            <source>Each Nᵢ,ₚ in the colour of Pᵢ&apos;s ring; the shaded band is the domain [uₚ, uₙ₊₁], the vertical line is u.</source>
            <translation>Each Nᵢ,ₚ in the colour of Pᵢ&apos;s ring; the shaded band is the domain [uₚ, uₙ₊₁], the vertical line is u.</translation>
        </message>
        <message>
            <source>Elevate the degree to %1</source>
            <translation>Elevate the degree to %1</translation>
        </message>
        <message>
            <source>Ex 2.2 as a B-spline (no interior knot)</source>
            <translation>Ex 2.2 as a B-spline (no interior knot)</translation>
        </message>
        <message>
            <source>Ex 2.2&apos;s Bézier curve as a B-spline; a uniform cubic closed on Ex 2.13&apos;s points; the circle and the conics, exactly, as rational curves.</source>
            <translation>Ex 2.2&apos;s Bézier curve as a B-spline; a uniform cubic closed on Ex 2.13&apos;s points; the circle and the conics, exactly, as rational curves.</translation>
        </message>
        <message>
            <source>Exact results</source>
            <translation>Exact results</translation>
        </message>
        <message>
            <source>Exact results and points</source>
            <translation>Exact results and points</translation>
        </message>
        <message>
            <source>Exact results: de Boor&apos;s net at u, the basis functions there, their supports, the knots with their multiplicities and the continuity of the curve at each.</source>
            <translation>Exact results: de Boor&apos;s net at u, the basis functions there, their supports, the knots with their multiplicities and the continuity of the curve at each.</translation>
        </message>
        <message>
            <source>Examples</source>
            <translation>Examples</translation>
        </message>
        <message>
            <source>Examples…</source>
            <translation>Examples…</translation>
        </message>
        <message>
            <source>Hide de Boor&apos;s net</source>
            <translation>Hide de Boor&apos;s net</translation>
        </message>
        <message>
            <source>Hide the Bézier segments</source>
            <translation>Hide the Bézier segments</translation>
        </message>
        <message>
            <source>Hide the cubic circle</source>
            <translation>Hide the cubic circle</translation>
        </message>
        <message>
            <source>Insert knot %1</source>
            <translation>Insert knot %1</translation>
        </message>
        <message>
            <source>Knot %1 inserted: %2 control points now, the same curve.</source>
            <translation>Knot %1 inserted: %2 control points now, the same curve.</translation>
        </message>
        <message>
            <source>Knot %1 removed: the curve is exactly the same.</source>
            <translation>Knot %1 removed: the curve is exactly the same.</translation>
        </message>
        <message>
            <source>Knot ruler</source>
            <translation>Knot ruler</translation>
        </message>
        <message>
            <source>Knots</source>
            <translation>Knots</translation>
        </message>
        <message>
            <source>Knots: %1</source>
            <translation>Knots: %1</translation>
        </message>
        <message>
            <source>Load %1</source>
            <translation>Load %1</translation>
        </message>
        <message>
            <source>Load Ex %1</source>
            <translation>Load Ex %1</translation>
        </message>
        <message>
            <source>Move knot u%1</source>
            <translation>Move knot u%1</translation>
        </message>
        <message>
            <source>Move u</source>
            <translation>Move u</translation>
        </message>
        <message>
            <source>Move u along the domain again and again; Pause makes it one undo step.</source>
            <translation>Move u along the domain again and again; Pause makes it one undo step.</translation>
        </message>
        <message>
            <source>No weights</source>
            <translation>No weights</translation>
        </message>
        <message>
            <source>One weight wᵢ &gt; 0 per point, separated by commas (1, 1, 2): a rational B-spline (NURBS), c(u) = Σ wᵢNᵢ,ₚPᵢ / Σ wᵢNᵢ,ₚ. Empty: polynomial.</source>
            <translation>One weight wᵢ &gt; 0 per point, separated by commas (1, 1, 2): a rational B-spline (NURBS), c(u) = Σ wᵢNᵢ,ₚPᵢ / Σ wᵢNᵢ,ₚ. Empty: polynomial.</translation>
        </message>
        <message>
            <source>Only a knot inside the domain can be removed; %1 is at its end or outside it.</source>
            <translation>Only a knot inside the domain can be removed; %1 is at its end or outside it.</translation>
        </message>
        <message>
            <source>Parameter u</source>
            <translation>Parameter u</translation>
        </message>
        <message>
            <source>Pause</source>
            <translation>Pause</translation>
        </message>
        <message>
            <source>Play</source>
            <translation>Play</translation>
        </message>
        <message>
            <source>Play u</source>
            <translation>Play u</translation>
        </message>
        <message>
            <source>Point %1 of the B-spline tab is not a finite number.</source>
            <translation>Point %1 of the B-spline tab is not a finite number.</translation>
        </message>
        <message>
            <source>Point %1 of the B-spline tab is not a pair of numbers.</source>
            <translation>Point %1 of the B-spline tab is not a pair of numbers.</translation>
        </message>
        <message>
            <source>Points</source>
            <translation>Points</translation>
        </message>
        <message>
            <source>Quarter circle: exact and cubic</source>
            <translation>Quarter circle: exact and cubic</translation>
        </message>
        <message>
            <source>Remove knot %1</source>
            <translation>Remove knot %1</translation>
        </message>
        <message>
            <source>Remove the knot selected on the ruler, only if the curve stays exactly the same.</source>
            <translation>Remove the knot selected on the ruler, only if the curve stays exactly the same.</translation>
        </message>
        <message>
            <source>Removing a knot would leave fewer than p + 1 = %1 points.</source>
            <translation>Removing a knot would leave fewer than p + 1 = %1 points.</translation>
        </message>
        <message>
            <source>Ruler keys: Left/Right select a knot, Shift+Left/Right move it, Insert inserts a knot at u, Delete removes the selected knot; Tab leaves the ruler.</source>
            <translation>Ruler keys: Left/Right select a knot, Shift+Left/Right move it, Insert inserts a knot at u, Delete removes the selected knot; Tab leaves the ruler.</translation>
        </message>
        <message>
            <source>Select a knot on the ruler first (click it, or Left/Right while the ruler has the focus).</source>
            <translation>Select a knot on the ruler first (click it, or Left/Right while the ruler has the focus).</translation>
        </message>
        <message>
            <source>Show de Boor&apos;s net</source>
            <translation>Show de Boor&apos;s net</translation>
        </message>
        <message>
            <source>Show the Bézier segments</source>
            <translation>Show the Bézier segments</translation>
        </message>
        <message>
            <source>Show the cubic circle</source>
            <translation>Show the cubic circle</translation>
        </message>
        <message>
            <source>Span k = %1: u&lt;sub&gt;%1&lt;/sub&gt; ≤ u &amp;lt; u&lt;sub&gt;%2&lt;/sub&gt;. Only P&lt;sub&gt;%3&lt;/sub&gt;…P&lt;sub&gt;%1&lt;/sub&gt; act here (local support); level r interpolates level r − 1 with α = (u − u&lt;sub&gt;j&lt;/sub&gt;)/(u&lt;sub&gt;j+p+1−r&lt;/sub&gt; − u&lt;sub&gt;j&lt;/sub&gt;).</source>
            <translation>Span k = %1: u&lt;sub&gt;%1&lt;/sub&gt; ≤ u &amp;lt; u&lt;sub&gt;%2&lt;/sub&gt;. Only P&lt;sub&gt;%3&lt;/sub&gt;…P&lt;sub&gt;%1&lt;/sub&gt; act here (local support); level r interpolates level r − 1 with α = (u − u&lt;sub&gt;j&lt;/sub&gt;)/(u&lt;sub&gt;j+p+1−r&lt;/sub&gt; − u&lt;sub&gt;j&lt;/sub&gt;).</translation>
        </message>
        <message>
            <source>Supports [uᵢ, uᵢ₊ₚ₊₁)</source>
            <translation>Supports [uᵢ, uᵢ₊ₚ₊₁)</translation>
        </message>
        <message>
            <source>The B-spline in the document is not valid: %1.</source>
            <translation>The B-spline in the document is not valid: %1.</translation>
        </message>
        <message>
            <source>The B-spline settings are not valid (“%1”).</source>
            <translation>The B-spline settings are not valid (“%1”).</translation>
        </message>
        <message>
            <source>The B-spline&apos;s control points are missing or not a list.</source>
            <translation>The B-spline&apos;s control points are missing or not a list.</translation>
        </message>
        <message>
            <source>The Bézier preset has degree n = number of points − 1, at most %1: remove points first.</source>
            <translation>The Bézier preset has degree n = number of points − 1, at most %1: remove points first.</translation>
        </message>
        <message>
            <source>The circle, exactly (NURBS)</source>
            <translation>The circle, exactly (NURBS)</translation>
        </message>
        <message>
            <source>The control points P0…Pn as numbers; fractions such as 1/3 are accepted.</source>
            <translation>The control points P0…Pn as numbers; fractions such as 1/3 are accepted.</translation>
        </message>
        <message>
            <source>The curve needs the knot %1: removing it would change the curve.</source>
            <translation>The curve needs the knot %1: removing it would change the curve.</translation>
        </message>
        <message>
            <source>The degree is at most %1.</source>
            <translation>The degree is at most %1.</translation>
        </message>
        <message>
            <source>The degree of every piece, 1 to 10: the curve is Cᵖ⁻¹ at a simple knot. Needs at least p + 1 points; the knots go back to the preset.</source>
            <translation>The degree of every piece, 1 to 10: the curve is Cᵖ⁻¹ at a simple knot. Needs at least p + 1 points; the knots go back to the preset.</translation>
        </message>
        <message>
            <source>The knots u₀ ≤ … ≤ uₙ₊ₚ₊₁: drag one (it never passes its neighbours), double-click to insert one, the badge is a knot&apos;s multiplicity. Bold: the domain [uₚ, uₙ₊₁]; yellow: the span that holds u.</source>
            <translation>The knots u₀ ≤ … ≤ uₙ₊ₚ₊₁: drag one (it never passes its neighbours), double-click to insert one, the badge is a knot&apos;s multiplicity. Bold: the domain [uₚ, uₙ₊₁]; yellow: the span that holds u.</translation>
        </message>
        <message>
            <source>The usual cubic Bézier quarter circle (1, 0), (1, k), (k, 1), (0, 1), k = 4(√2 − 1)/3, dashed: close to the circle but not on it (its radial error is in the exact panel); the rational quarter circle is exact.</source>
            <translation>The usual cubic Bézier quarter circle (1, 0), (1, k), (k, 1), (0, 1), k = 4(√2 − 1)/3, dashed: close to the circle but not on it (its radial error is in the exact panel); the rational quarter circle is exact.</translation>
        </message>
        <message>
            <source>This B-spline cannot be drawn: %1</source>
            <translation>This B-spline cannot be drawn: %1</translation>
        </message>
        <message>
            <source>Closed uniform cubic (Ex 2.13)</source>
            <translation>Closed uniform cubic (Ex 2.13)</translation>
        </message>
        <message>
            <source>Weights are numbers separated by commas, such as 1, 1, 2 or 1, 1/2, 1; empty for none.</source>
            <translation>Weights are numbers separated by commas, such as 1, 1, 2 or 1, 1/2, 1; empty for none.</translation>
        </message>
        <message>
            <source>Weights: %1</source>
            <translation>Weights: %1</translation>
        </message>
        <message>
            <source>broken</source>
            <translation>broken</translation>
        </message>
        <message>
            <source>c(u) = Σ Nᵢ,ₚ(u) Pᵢ: the weight of each control point along the curve. Nᵢ,ₚ is zero outside [uᵢ, uᵢ₊ₚ₊₁) (local support), the functions add up to 1 on the domain (the dashed line), and at a knot of multiplicity m they are Cᵖ⁻ᵐ.</source>
            <translation>c(u) = Σ Nᵢ,ₚ(u) Pᵢ: the weight of each control point along the curve. Nᵢ,ₚ is zero outside [uᵢ, uᵢ₊ₚ₊₁) (local support), the functions add up to 1 on the domain (the dashed line), and at a knot of multiplicity m they are Cᵖ⁻ᵐ.</translation>
        </message>
        <message>
            <source>clamped (open uniform)</source>
            <translation>clamped (open uniform)</translation>
        </message>
        <message>
            <source>continuity C&lt;sup&gt;p−m&lt;/sup&gt;</source>
            <translation>continuity C&lt;sup&gt;p−m&lt;/sup&gt;</translation>
        </message>
        <message>
            <source>de Boor&apos;s &amp;net at u</source>
            <translation>de Boor&apos;s &amp;net at u</translation>
        </message>
        <message>
            <source>de Boor&apos;s algorithm at u = %1</source>
            <translation>de Boor&apos;s algorithm at u = %1</translation>
        </message>
        <message>
            <source>de Boor&apos;s algorithm at u step by step: level r interpolates level r − 1, one colour per level as in the De Casteljau tab, from the span&apos;s p + 1 points down to c(u).</source>
            <translation>de Boor&apos;s algorithm at u step by step: level r interpolates level r − 1, one colour per level as in the De Casteljau tab, from the span&apos;s p + 1 points down to c(u).</translation>
        </message>
        <message>
            <source>degree %1 needs at least %2 points</source>
            <translation>degree %1 needs at least %2 points</translation>
        </message>
        <message>
            <source>edited</source>
            <translation>edited</translation>
        </message>
        <message>
            <source>knot</source>
            <translation>knot</translation>
        </message>
        <message>
            <source>level r</source>
            <translation>level r</translation>
        </message>
        <message>
            <source>multiplicity m</source>
            <translation>multiplicity m</translation>
        </message>
        <message>
            <source>non-zero on</source>
            <translation>non-zero on</translation>
        </message>
        <message>
            <source>none (polynomial)</source>
            <translation>none (polynomial)</translation>
        </message>
        <message>
            <source>outside or at an end</source>
            <translation>outside or at an end</translation>
        </message>
        <message>
            <source>points P&lt;sub&gt;j&lt;/sub&gt;&lt;sup&gt;r&lt;/sup&gt;</source>
            <translation>points P&lt;sub&gt;j&lt;/sub&gt;&lt;sup&gt;r&lt;/sup&gt;</translation>
        </message>
        <message>
            <source>u = %1 is a knot of multiplicity %2 already: once more would break the curve (at most p = %3 times).</source>
            <translation>u = %1 is a knot of multiplicity %2 already: once more would break the curve (at most p = %3 times).</translation>
        </message>
        <message>
            <source>u in the domain [uₚ, uₙ₊₁]: the point c(u) and de Boor&apos;s net there.</source>
            <translation>u in the domain [uₚ, uₙ₊₁]: the point c(u) and de Boor&apos;s net there.</translation>
        </message>
        <message>
            <source>uniform</source>
            <translation>uniform</translation>
        </message>
        <message>
            <source>value</source>
            <translation>value</translation>
        </message>
        <message>
            <source>Σ N&lt;sub&gt;i,p&lt;/sub&gt;(u) = %1: partition of unity</source>
            <translation>Σ N&lt;sub&gt;i,p&lt;/sub&gt;(u) = %1: partition of unity</translation>
        </message>
        <message>
            <source>An inset with the curve as the projection of a polynomial B-spline in space: the points Hᵢ = (wᵢxᵢ, wᵢyᵢ, wᵢ) (purple), the polynomial curve through them, and the rays from the origin O through each Hᵢ down to the plane w = 1, where they meet Pᵢ and the rational curve.</source>
            <translation>An inset with the curve as the projection of a polynomial B-spline in space: the points Hᵢ = (wᵢxᵢ, wᵢyᵢ, wᵢ) (purple), the polynomial curve through them, and the rays from the origin O through each Hᵢ down to the plane w = 1, where they meet Pᵢ and the rational curve.</translation>
        </message>
        <message>
            <source>Change the weight of P%1</source>
            <translation>Change the weight of P%1</translation>
        </message>
        <message>
            <source>Curvature κ against arc length s</source>
            <translation>Curvature κ against arc length s</translation>
        </message>
        <message>
            <source>Curvature κ(s) in the &amp;plot</source>
            <translation>Curvature κ(s) in the &amp;plot</translation>
        </message>
        <message>
            <source>Drag a point to move it; double-click to add one; Delete removes the selected point; drag the paper to pan, wheel to zoom; Shift+wheel over a point changes its weight. The ringed points are the p + 1 that act at u.</source>
            <translation>Drag a point to move it; double-click to add one; Delete removes the selected point; drag the paper to pan, wheel to zoom; Shift+wheel over a point changes its weight. The ringed points are the p + 1 that act at u.</translation>
        </message>
        <message>
            <source>Hide the homogeneous curve</source>
            <translation>Hide the homogeneous curve</translation>
        </message>
        <message>
            <source>Homo&amp;geneous curve (wx, wy, w)</source>
            <translation>Homo&amp;geneous curve (wx, wy, w)</translation>
        </message>
        <message>
            <source>Plot the basis functions</source>
            <translation>Plot the basis functions</translation>
        </message>
        <message>
            <source>Plot the curvature</source>
            <translation>Plot the curvature</translation>
        </message>
        <message>
            <source>Plot the signed curvature κ of the curve against its arc length s instead of the basis functions, each interior knot labelled with the continuity Cᵖ⁻ᵐ there: κ may jump at a knot of multiplicity p − 1 (C¹) and the curve may turn a corner at one of multiplicity p (C⁰).</source>
            <translation>Plot the signed curvature κ of the curve against its arc length s instead of the basis functions, each interior knot labelled with the continuity Cᵖ⁻ᵐ there: κ may jump at a knot of multiplicity p − 1 (C¹) and the curve may turn a corner at one of multiplicity p (C⁰).</translation>
        </message>
        <message>
            <source>Show the homogeneous curve</source>
            <translation>Show the homogeneous curve</translation>
        </message>
        <message>
            <source>The curve in (wx, wy, w)</source>
            <translation>The curve in (wx, wy, w)</translation>
        </message>
        <message>
            <source>The weight of P%1 is already %2, the largest the canvas reaches.</source>
            <translation>The weight of P%1 is already %2, the largest the canvas reaches.</translation>
        </message>
        <message>
            <source>The weight of P%1 is already %2, the smallest the canvas reaches.</source>
            <translation>The weight of P%1 is already %2, the smallest the canvas reaches.</translation>
        </message>
        <message>
            <source>arc length s</source>
            <translation>arc length s</translation>
        </message>
        <message>
            <source>curvature κ</source>
            <translation>curvature κ</translation>
        </message>
        <message>
            <source>κ = (x′y″ − y′x″)/|c′|³, positive where the curve turns left, computed on each Bézier piece of the curve. At a knot of multiplicity m the curve is Cᵖ⁻ᵐ: κ is continuous where the curve is C², it may jump at C¹ (a break in the line), and at C⁰ the curve may turn a corner.</source>
            <translation>κ = (x′y″ − y′x″)/|c′|³, positive where the curve turns left, computed on each Bézier piece of the curve. At a knot of multiplicity m the curve is Cᵖ⁻ᵐ: κ is continuous where the curve is C², it may jump at C¹ (a break in the line), and at C⁰ the curve may turn a corner.</translation>
        </message>
        <message>
            <source>κ(s) of the curve; the light vertical lines are its interior knots, each labelled with the continuity there.</source>
            <translation>κ(s) of the curve; the light vertical lines are its interior knots, each labelled with the continuity there.</translation>
        </message>
        <message>
            <source>Keys: ] and [ pick a point, arrows nudge it (Shift: ×10), + and − change its weight, Delete removes it; Tab leaves the canvas.</source>
            <translation>Keys: ] and [ pick a point, arrows nudge it (Shift: ×10), + and − change its weight, Delete removes it; Tab leaves the canvas.</translation>
        </message>
        <message>
            <source>The weight wᵢ of each point (a rational B-spline when not all are 1)</source>
            <translation>The weight wᵢ of each point (a rational B-spline when not all are 1)</translation>
        </message>
        <message>
            <source>“%1” is not a weight: type a decimal (0.7) or a fraction (3/2) greater than 0.</source>
            <translation>“%1” is not a weight: type a decimal (0.7) or a fraction (3/2) greater than 0.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::ConventionsTable</name>
        <message>
            <source>From τ</source>
            <translation>From τ</translation>
        </message>
        <message>
            <source>Granota, the thesis (Def 2.8)</source>
            <translation>Granota, the thesis (Def 2.8)</translation>
        </message>
        <message>
            <source>Kochanek–Bartels (C = B = 0)</source>
            <translation>Kochanek–Bartels (C = B = 0)</translation>
        </message>
        <message>
            <source>Parameter</source>
            <translation>Parameter</translation>
        </message>
        <message>
            <source>Primer on Bézier curves</source>
            <translation>Primer on Bézier curves</translation>
        </message>
        <message>
            <source>Processing</source>
            <translation>Processing</translation>
        </message>
        <message>
            <source>Source</source>
            <translation>Source</translation>
        </message>
        <message>
            <source>Tension conventions</source>
            <translation>Tension conventions</translation>
        </message>
        <message>
            <source>The same Catmull-Rom tangent τ(qᵢ₊₁ − qᵢ₋₁) in each source&apos;s convention, with its value for the curve shown: the selected τ, the cardinal c, or T of the selected point.</source>
            <translation>The same Catmull-Rom tangent τ(qᵢ₊₁ − qᵢ₋₁) in each source&apos;s convention, with its value for the curve shown: the selected τ, the cardinal c, or T of the selected point.</translation>
        </message>
        <message>
            <source>Value</source>
            <translation>Value</translation>
        </message>
        <message>
            <source>d3-shape</source>
            <translation>d3-shape</translation>
        </message>
        <message>
            <source>none (τ ≤ 0)</source>
            <translation>none (τ ≤ 0)</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::CurveFamilyNames</name>
        <message>
            <source>Cardinal (one tension c)</source>
            <translation>Cardinal (one tension c)</translation>
        </message>
        <message>
            <source>Catmull-Rom (Def 2.10)</source>
            <translation>Catmull-Rom (Def 2.10)</translation>
        </message>
        <message>
            <source>C² spline in the plane (Def 2.1)</source>
            <translation>C² spline in the plane (Def 2.1)</translation>
        </message>
        <message>
            <source>Function data y(x) (Def 2.3)</source>
            <translation>Function data y(x) (Def 2.3)</translation>
        </message>
        <message>
            <source>Hermite (drag the tangents)</source>
            <translation>Hermite (drag the tangents)</translation>
        </message>
        <message>
            <source>Kochanek–Bartels: T, C, B per point</source>
            <translation>Kochanek–Bartels: T, C, B per point</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::FamilyPanel</name>
        <message>
            <source>All points</source>
            <translation>All points</translation>
        </message>
        <message>
            <source>Back to the Catmull-Rom tangents</source>
            <translation>Back to the Catmull-Rom tangents</translation>
        </message>
        <message>
            <source>Bias B = %1:</source>
            <translation>Bias B = %1:</translation>
        </message>
        <message>
            <source>Bias B in steps of 1/20: &gt; 0 leans the tangents towards the incoming chord, &lt; 0 towards the outgoing one.</source>
            <translation>Bias B in steps of 1/20: &gt; 0 leans the tangents towards the incoming chord, &lt; 0 towards the outgoing one.</translation>
        </message>
        <message>
            <source>Continuity C = %1:</source>
            <translation>Continuity C = %1:</translation>
        </message>
        <message>
            <source>Continuity C in steps of 1/20: 0 keeps the curve C¹ (Prop 2.3); any other value makes the two tangents differ; −1 gives corners.</source>
            <translation>Continuity C in steps of 1/20: 0 keeps the curve C¹ (Prop 2.3); any other value makes the two tangents differ; −1 gives corners.</translation>
        </message>
        <message>
            <source>Def 2.8 builds each segment from two points and two tangents. Catmull-Rom sets the tangents by the rule τ(qᵢ₊₁ − qᵢ₋₁); cardinal and Kochanek–Bartels by other rules; Hermite lets you drag them; the C² splines solve for them.</source>
            <translation>Def 2.8 builds each segment from two points and two tangents. Catmull-Rom sets the tangents by the rule τ(qᵢ₊₁ − qᵢ₋₁); cardinal and Kochanek–Bartels by other rules; Hermite lets you drag them; the C² splines solve for them.</translation>
        </message>
        <message>
            <source>Every tangent as the Catmull-Rom rule τ(qᵢ₊₁ − qᵢ₋₁) of the selected τ sets it.</source>
            <translation>Every tangent as the Catmull-Rom rule τ(qᵢ₊₁ − qᵢ₋₁) of the selected τ sets it.</translation>
        </message>
        <message>
            <source>Every tangent is yours: drag the square at its end, or Alt + arrows for the selected point&apos;s.</source>
            <translation>Every tangent is yours: drag the square at its end, or Alt + arrows for the selected point&apos;s.</translation>
        </message>
        <message>
            <source>Famil&amp;y:</source>
            <translation>Famil&amp;y:</translation>
        </message>
        <message>
            <source>Family: how the tangents are chosen</source>
            <translation>Family: how the tangents are chosen</translation>
        </message>
        <message>
            <source>Move T, C, B of every point at once (also when no point is selected).</source>
            <translation>Move T, C, B of every point at once (also when no point is selected).</translation>
        </message>
        <message>
            <source>T, C, B of every point:</source>
            <translation>T, C, B of every point:</translation>
        </message>
        <message>
            <source>T, C, B of the selected point q%1:</source>
            <translation>T, C, B of the selected point q%1:</translation>
        </message>
        <message>
            <source>Tangents set by a rule: (1 − c)(qᵢ₊₁ − qᵢ₋₁)/2, Catmull-Rom with τ = (1 − c)/2.</source>
            <translation>Tangents set by a rule: (1 − c)(qᵢ₊₁ − qᵢ₋₁)/2, Catmull-Rom with τ = (1 − c)/2.</translation>
        </message>
        <message>
            <source>Tangents set by a rule: T scales them, C ≠ 0 makes the incoming and outgoing tangents differ (a corner), B leans them towards one chord.</source>
            <translation>Tangents set by a rule: T scales them, C ≠ 0 makes the incoming and outgoing tangents differ (a corner), B leans them towards one chord.</translation>
        </message>
        <message>
            <source>Tension T = %1:</source>
            <translation>Tension T = %1:</translation>
        </message>
        <message>
            <source>Tension T in steps of 1/20: τ = (1 − T)/2; 1 gives zero tangents.</source>
            <translation>Tension T in steps of 1/20: τ = (1 − T)/2; 1 gives zero tangents.</translation>
        </message>
        <message>
            <source>The cardinal tension c in steps of 1/20 from −1 to 1: c = 0 is Catmull-Rom&apos;s τ = 1/2, c = 1 gives zero tangents (straight segments).</source>
            <translation>The cardinal tension c in steps of 1/20 from −1 to 1: c = 0 is Catmull-Rom&apos;s τ = 1/2, c = 1 gives zero tangents (straight segments).</translation>
        </message>
        <message>
            <source>c = %1 (τ = %2):</source>
            <translation>c = %1 (τ = %2):</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::KnotContinuityTable</name>
        <message>
            <source>Continuity at the knots</source>
            <translation>Continuity at the knots</translation>
        </message>
        <message>
            <source>Each knot of the curve drawn: ✓ where the derivatives of order 0, 1, 2 agree (C⁰, C¹, C²) and where the direction (G¹) and the curvature (G²) agree; the last column is the jump of the tangent. Catmull-Rom curves are C¹ at every knot (Prop 2.3); a continuity C ≠ 0 breaks it.</source>
            <translation>Each knot of the curve drawn: ✓ where the derivatives of order 0, 1, 2 agree (C⁰, C¹, C²) and where the direction (G¹) and the curvature (G²) agree; the last column is the jump of the tangent. Catmull-Rom curves are C¹ at every knot (Prop 2.3); a continuity C ≠ 0 breaks it.</translation>
        </message>
        <message>
            <source>Knot</source>
            <translation>Knot</translation>
        </message>
        <message>
            <source>|p′₊ − p′₋|</source>
            <translation>|p′₊ − p′₋|</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::FunctionDataCurves</name>
        <message>
            <source>A point is not a finite number.</source>
            <translation>A point is not a finite number.</translation>
        </message>
        <message>
            <source>Catmull-Rom τ = 1/2</source>
            <translation>Catmull-Rom τ = 1/2</translation>
        </message>
        <message>
            <source>Fritsch–Carlson</source>
            <translation>Fritsch–Carlson</translation>
        </message>
        <message>
            <source>Function data need at least 2 points.</source>
            <translation>Function data need at least 2 points.</translation>
        </message>
        <message>
            <source>Steffen</source>
            <translation>Steffen</translation>
        </message>
        <message>
            <source>The curve overflows: the coordinates are too large.</source>
            <translation>The curve overflows: the coordinates are too large.</translation>
        </message>
        <message>
            <source>The points are not data y(x): their abscissae must increase strictly from q0 to qn. Move a point, or choose another family: the points are kept.</source>
            <translation>The points are not data y(x): their abscissae must increase strictly from q0 to qn. Move a point, or choose another family: the points are kept.</translation>
        </message>
        <message>
            <source>natural spline</source>
            <translation>natural spline</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::FunctionDataPanel</name>
        <message>
            <source>Curve</source>
            <translation>Curve</translation>
        </message>
        <message>
            <source>Curves on the data</source>
            <translation>Curves on the data</translation>
        </message>
        <message>
            <source>Interval</source>
            <translation>Interval</translation>
        </message>
        <message>
            <source>Largest overshoot beyond the neighbouring data values:</source>
            <translation>Largest overshoot beyond the neighbouring data values:</translation>
        </message>
        <message>
            <source>Largest overshoot of each curve</source>
            <translation>Largest overshoot of each curve</translation>
        </message>
        <message>
            <source>On each interval [xᵢ, xᵢ₊₁], fill the part of a curve outside the band between yᵢ and yᵢ₊₁: where it goes beyond its neighbouring data values.</source>
            <translation>On each interval [xᵢ, xᵢ₊₁], fill the part of a curve outside the band between yᵢ and yᵢ₊₁: where it goes beyond its neighbouring data values.</translation>
        </message>
        <message>
            <source>Overshoot</source>
            <translation>Overshoot</translation>
        </message>
        <message>
            <source>Overshoot shading</source>
            <translation>Overshoot shading</translation>
        </message>
        <message>
            <source>Shade the o&amp;vershoot</source>
            <translation>Shade the o&amp;vershoot</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::PlaneSplineCurves</name>
        <message>
            <source>A closed C² spline needs at least 3 points.</source>
            <translation>A closed C² spline needs at least 3 points.</translation>
        </message>
        <message>
            <source>A point or an end tangent is not a finite number.</source>
            <translation>A point or an end tangent is not a finite number.</translation>
        </message>
        <message>
            <source>An open C² spline needs at least 2 points.</source>
            <translation>An open C² spline needs at least 2 points.</translation>
        </message>
        <message>
            <source>C² spline</source>
            <translation>C² spline</translation>
        </message>
        <message>
            <source>C² spline, %1</source>
            <translation>C² spline, %1</translation>
        </message>
        <message>
            <source>Points q%1 and q%2 coincide: %3 parameters need distinct consecutive points (use uniform parameters, or move one).</source>
            <translation>Points q%1 and q%2 coincide: %3 parameters need distinct consecutive points (use uniform parameters, or move one).</translation>
        </message>
        <message>
            <source>The spline overflows: the coordinates are too large.</source>
            <translation>The spline overflows: the coordinates are too large.</translation>
        </message>
        <message>
            <source>centripetal</source>
            <translation>centripetal</translation>
        </message>
        <message>
            <source>chord length</source>
            <translation>chord length</translation>
        </message>
        <message>
            <source>clamped</source>
            <translation>clamped</translation>
        </message>
        <message>
            <source>dashed: Catmull-Rom τ = 1/2 (C¹)</source>
            <translation>dashed: Catmull-Rom τ = 1/2 (C¹)</translation>
        </message>
        <message>
            <source>natural</source>
            <translation>natural</translation>
        </message>
        <message>
            <source>not-a-knot</source>
            <translation>not-a-knot</translation>
        </message>
        <message>
            <source>periodic (closed)</source>
            <translation>periodic (closed)</translation>
        </message>
        <message>
            <source>uniform</source>
            <translation>uniform</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::PlaneSplinePanel</name>
        <message>
            <source>&amp;Final tangent:</source>
            <translation>&amp;Final tangent:</translation>
        </message>
        <message>
            <source>&amp;Initial tangent:</source>
            <translation>&amp;Initial tangent:</translation>
        </message>
        <message>
            <source>A tangent component is a number between −%1 and %1, such as 1/2 or -0.25.</source>
            <translation>A tangent component is a number between −%1 and %1, such as 1/2 or -0.25.</translation>
        </message>
        <message>
            <source>Catmull-Rom comparison</source>
            <translation>Catmull-Rom comparison</translation>
        </message>
        <message>
            <source>Catmull-Rom τ = 1/2 of the same points</source>
            <translation>Catmull-Rom τ = 1/2 of the same points</translation>
        </message>
        <message>
            <source>C² spline end tangents</source>
            <translation>C² spline end tangents</translation>
        </message>
        <message>
            <source>C² spline ends</source>
            <translation>C² spline ends</translation>
        </message>
        <message>
            <source>C² spline parameters</source>
            <translation>C² spline parameters</translation>
        </message>
        <message>
            <source>Def 2.1 leaves two conditions free; the ends fix them. Natural: p″ = 0 at both ends. Clamped: the given end tangents. Not-a-knot: p‴ continuous at the second and last but one points. Periodic: a closed curve, C² at every point.</source>
            <translation>Def 2.1 leaves two conditions free; the ends fix them. Natural: p″ = 0 at both ends. Clamped: the given end tangents. Not-a-knot: p‴ continuous at the second and last but one points. Periodic: a closed curve, C² at every point.</translation>
        </message>
        <message>
            <source>End c&amp;onditions:</source>
            <translation>End c&amp;onditions:</translation>
        </message>
        <message>
            <source>Final tangent, %1</source>
            <translation>Final tangent, %1</translation>
        </message>
        <message>
            <source>How the parameter advances from point to point: by 1 (uniform), by the distance (chord length) or by its square root (centripetal).</source>
            <translation>How the parameter advances from point to point: by 1 (uniform), by the distance (chord length) or by its square root (centripetal).</translation>
        </message>
        <message>
            <source>Initial tangent, %1</source>
            <translation>Initial tangent, %1</translation>
        </message>
        <message>
            <source>Knot spacin&amp;g:</source>
            <translation>Knot spacin&amp;g:</translation>
        </message>
        <message>
            <source>x component</source>
            <translation>x component</translation>
        </message>
        <message>
            <source>y component</source>
            <translation>y component</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::SplineFamilyPanels</name>
        <message>
            <source>C² spline in the plane</source>
            <translation>C² spline in the plane</translation>
        </message>
        <message>
            <source>Data where the natural spline dips about 98 below its neighbouring values (d3-shape issue #38); the monotone schemes do not.</source>
            <translation>Data where the natural spline dips about 98 below its neighbouring values (d3-shape issue #38); the monotone schemes do not.</translation>
        </message>
        <message>
            <source>Example: d3-s&amp;hape #38 data</source>
            <translation>Example: d3-s&amp;hape #38 data</translation>
        </message>
        <message>
            <source>Example: t&amp;he frog&apos;s outline points</source>
            <translation>Example: t&amp;he frog&apos;s outline points</translation>
        </message>
        <message>
            <source>Frog outline example</source>
            <translation>Frog outline example</translation>
        </message>
        <message>
            <source>Function data</source>
            <translation>Function data</translation>
        </message>
        <message>
            <source>The frog body&apos;s vertices at rest, closed: the C² spline against the Catmull-Rom outline of §4.12.</source>
            <translation>The frog body&apos;s vertices at rest, closed: the C² spline against the Catmull-Rom outline of §4.12.</translation>
        </message>
        <message>
            <source>d3-shape #38 example</source>
            <translation>d3-shape #38 example</translation>
        </message>
    </context>
    <context>
        <name>FamilyReport</name>
        <message numerus="yes">
            <source>… and %n more segments.</source>
            <translation>
                <numerusform>… and %n more segment.</numerusform>
                <numerusform>… and %n more segments.</numerusform>
            </translation>
        </message>
        <message>
            <source>Centripetal and chordal spacing: values in decimals.</source>
            <translation>Centripetal and chordal spacing: values in decimals.</translation>
        </message>
        <message>
            <source>Def 2.8 with the tangents you set: drag the handle at the end of each tangent.</source>
            <translation>Def 2.8 with the tangents you set: drag the handle at the end of each tangent.</translation>
        </message>
        <message>
            <source>Each point has two tangents (Kochanek and Bartels 1984): in ends the segment arriving, out starts the segment leaving; they differ when C ≠ 0, and the curve is then not C¹ there.</source>
            <translation>Each point has two tangents (Kochanek and Bartels 1984): in ends the segment arriving, out starts the segment leaving; they differ when C ≠ 0, and the curve is then not C¹ there.</translation>
        </message>
        <message>
            <source>Function data y(x): the natural spline, Catmull-Rom, Fritsch–Carlson and Steffen on the same data, their overshoot shaded on the canvas and measured in their panel. This panel lists the exact tangents and segments of the cardinal, Kochanek–Bartels and Hermite families.</source>
            <translation>Function data y(x): the natural spline, Catmull-Rom, Fritsch–Carlson and Steffen on the same data, their overshoot shaded on the canvas and measured in their panel. This panel lists the exact tangents and segments of the cardinal, Kochanek–Bartels and Hermite families.</translation>
        </message>
        <message>
            <source>Segments as Hermite data (Def 2.8)</source>
            <translation>Segments as Hermite data (Def 2.8)</translation>
        </message>
        <message>
            <source>Segments as cubic Bézier curves</source>
            <translation>Segments as cubic Bézier curves</translation>
        </message>
        <message>
            <source>Tangents at the points</source>
            <translation>Tangents at the points</translation>
        </message>
        <message>
            <source>The C² spline in the plane (Def 2.1) solves for its tangents: its end conditions and parameters are in its panel, the continuity at every knot in the Knots tab. This panel lists the exact tangents and segments of the cardinal, Kochanek–Bartels and Hermite families.</source>
            <translation>The C² spline in the plane (Def 2.1) solves for its tangents: its end conditions and parameters are in its panel, the continuity at every knot in the Knots tab. This panel lists the exact tangents and segments of the cardinal, Kochanek–Bartels and Hermite families.</translation>
        </message>
        <message>
            <source>The points or the tangents are not small fractions: values in decimals.</source>
            <translation>The points or the tangents are not small fractions: values in decimals.</translation>
        </message>
        <message>
            <source>The tangent at qᵢ is τ(qᵢ₊₁ − qᵢ₋₁) with τ = (1 − c)/2 = %1 (c = %2).</source>
            <translation>The tangent at qᵢ is τ(qᵢ₊₁ − qᵢ₋₁) with τ = (1 − c)/2 = %1 (c = %2).</translation>
        </message>
        <message>
            <source>in</source>
            <translation>in</translation>
        </message>
        <message>
            <source>out</source>
            <translation>out</translation>
        </message>
        <message>
            <source>segment</source>
            <translation>segment</translation>
        </message>
        <message>
            <source>tangent</source>
            <translation>tangent</translation>
        </message>
        <message>
            <source>Def 2.1 in the plane: each segment pᵢ(s) from qᵢ to qᵢ₊₁, s ∈ [0, 1], in powers of s, solved exactly; the curve is C² at every knot (the Knots tab).</source>
            <translation>Def 2.1 in the plane: each segment pᵢ(s) from qᵢ to qᵢ₊₁, s ∈ [0, 1], in powers of s, solved exactly; the curve is C² at every knot (the Knots tab).</translation>
        </message>
    </context>
</TS>
