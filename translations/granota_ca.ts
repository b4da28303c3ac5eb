<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ca_ES">
    <context>
        <name>CatmullRomCurves</name>
        <message>
            <location filename="../ui/catmull_rom_curves.cpp" line="58" />
            <source>An open curve needs at least 2 points.</source>
            <translation>Una corba oberta necessita almenys 2 punts.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_curves.cpp" line="59" />
            <source>A single segment (Def 2.8) needs at least 4 points.</source>
            <translation>Un sol segment (Def. 2.8) necessita almenys 4 punts.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_curves.cpp" line="60" />
            <source>A cyclic or closed curve needs at least 3 points.</source>
            <translation>Una corba cíclica o tancada necessita almenys 3 punts.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_curves.cpp" line="62" />
            <source>A point or a tension is not a finite number.</source>
            <translation>Un punt o una tensió no és un nombre finit.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_curves.cpp" line="63" />
            <source>The curve overflows: the coordinates are too large.</source>
            <translation>La corba desborda: les coordenades són massa grans.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_curves.cpp" line="65" />
            <source>No cubic spline (Def 2.3): the points are not a function of x — their abscissae must increase strictly from q0 to qn.</source>
            <translation>No hi ha spline cúbic (Def. 2.3): els punts no són una funció de x — les seues abscisses han de créixer estrictament de q0 a qn.</translation>
        </message>
        <message>
            <source>No unique cubic spline with these ends: as Ex 2.1, the last but one abscissa must not be 0.</source>
            <translation>No hi ha un únic spline cúbic amb aquests extrems: com a l&apos;Ex. 2.1, la penúltima abscissa no pot ser 0.</translation>
        </message>
    </context>
    <context>
        <name>CatmullRomReport</name>
        <message numerus="yes">
            <location filename="../ui/catmull_rom_report.cpp" line="62" />
            <source>… and %n more segments.</source>
            <translation>
                <numerusform>… i %n segments més.</numerusform>
                <numerusform>… i %n segments més.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="71" />
            <source>%1 jumps at x = %2: left %3, right %4 (jump %5)</source>
            <translation>%1 fa un salt a x = %2: per l'esquerra %3, per la dreta %4 (salt %5)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="75" />
            <source>%1 does not interpolate (%2, %3): %1(%2) = %4</source>
            <translation>%1 no interpola (%2, %3): %1(%2) = %4</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="79" />
            <source>The point (%1, %2) lies outside the domain.</source>
            <translation>El punt (%1, %2) és fora del domini.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="91" />
            <source>not continuous</source>
            <translation>no és contínua</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="94" />
            <source>C^%1 at every knot</source>
            <translation>C^%1 a tots els nusos</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="97" />
            <source>C^%1, not C^%2</source>
            <translation>C^%1, però no C^%2</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/catmull_rom_report.cpp" line="101" />
            <source>interpolates all %n points</source>
            <translation>
                <numerusform>interpola els %n punts</numerusform>
                <numerusform>interpola els %n punts</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="103" />
            <source>does not interpolate every point</source>
            <translation>no interpola tots els punts</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="117" />
            <location filename="../ui/catmull_rom_report.cpp" line="180" />
            <source>knot</source>
            <translation>nus</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="147" />
            <source>no interior knot</source>
            <translation>cap nus interior</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/catmull_rom_report.cpp" line="150" />
            <source>equal tangents at all %n knots (C¹)</source>
            <translation>
                <numerusform>tangents iguals als %n nusos (C¹)</numerusform>
                <numerusform>tangents iguals als %n nusos (C¹)</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="153" />
            <source>C² too (p″ matches)</source>
            <translation>també C² (p″ coincideix)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="154" />
            <source>not C²: p″ jumps</source>
            <translation>no és C²: p″ fa un salt</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/catmull_rom_report.cpp" line="158" />
            <source>parallel tangents at all %n knots (G¹), not equal ones (C¹) in the local parameters</source>
            <translation>
                <numerusform>tangents paral·leles als %n nusos (G¹), no iguals (C¹) en els paràmetres locals</numerusform>
                <numerusform>tangents paral·leles als %n nusos (G¹), no iguals (C¹) en els paràmetres locals</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="163" />
            <source>the tangents differ at some knots</source>
            <translation>les tangents difereixen en alguns nusos</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="180" />
            <source>end of the segment before</source>
            <translation>final del segment anterior</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="181" />
            <source>start of the segment after</source>
            <translation>inici del segment següent</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="188" />
            <source>Matrix form (Lemma 2.3)</source>
            <translation>Forma matricial (Lema 2.3)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="207" />
            <source>Blending functions wⱼ(t, τ) (Def 2.9, Cor 2.1)</source>
            <translation>Funcions de mescla wⱼ(t, τ) (Def. 2.9, Cor. 2.1)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="220" />
            <source>Processing's curveTightness</source>
            <translation>El curveTightness de Processing</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="221" />
            <source>Processing draws the same curves with curveTightness(s), τ = (1 − s)/2: s = 0 (its default) is τ = 1/2.</source>
            <translation>Processing dibuixa les mateixes corbes amb curveTightness(s), τ = (1 − s)/2: s = 0 (el valor per defecte) és τ = 1/2.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="255" />
            <source>Ex 2.1 as printed in the thesis</source>
            <translation>L'Ex. 2.1 tal com apareix a la tesi</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="261" />
            <source>The check of Def 2.3 on the printed pieces:</source>
            <translation>La comprovació de la Def. 2.3 sobre els trossos impresos:</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="267" />
            <source>%1 as printed misses both of its points by the same constant: it lacks %2.</source>
            <translation>%1 tal com està imprès s'allunya dels seus dos punts en la mateixa constant: li falta %2.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="270" />
            <source>Correct %1:</source>
            <translation>%1 correcte:</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="275" />
            <source>The corrected spline:</source>
            <translation>L'spline corregit:</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="277" />
            <source>Ex 2.1's spline is a cubic spline (Def 2.3) but not the natural one: s″ ≠ 0 at its ends, so its pieces differ from those above.</source>
            <translation>L'spline de l'Ex. 2.1 és un spline cúbic (Def. 2.3) però no el natural: s″ ≠ 0 als extrems, i per això els seus trossos difereixen dels de dalt.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="286" />
            <source>Cubic spline C² (Def 2.3), natural ends</source>
            <translation>Spline cúbic C² (Def. 2.3), extrems naturals</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="309" />
            <source>In decimals, each piece in powers of u = x − xᵢ:</source>
            <translation>En decimals, cada tros en potències de u = x − xᵢ:</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="326" />
            <source>open</source>
            <translation>oberta</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="327" />
            <source>cyclic</source>
            <translation>cíclica</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="328" />
            <source>closed</source>
            <translation>tancada</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="329" />
            <source>single segment</source>
            <translation>un sol segment</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="351" />
            <source>Segments, t ∈ [0, 1]: %1</source>
            <translation>Segments, t ∈ [0, 1]: %1</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="353" />
            <source>Centripetal and chordal spacing: coefficients in decimals.</source>
            <translation>Parametrització centrípeta o per longitud de corda: coeficients en decimals.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="354" />
            <source>The points are not small fractions: coefficients in decimals.</source>
            <translation>Els punts no són fraccions petites: coeficients en decimals.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="370" />
            <source>Tangents at the knots (Prop 2.3)</source>
            <translation>Tangents als nusos (Prop. 2.3)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="371" />
            <source>Catmull-Rom curves are C¹: at every knot cᵢ′(1) = cᵢ₊₁′(0) = τ(qᵢ₊₁ − qᵢ₋₁).</source>
            <translation>Les corbes de Catmull-Rom són C¹: a cada nus cᵢ′(1) = cᵢ₊₁′(0) = τ(qᵢ₊₁ − qᵢ₋₁).</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="394" />
            <source>Smoothness compared (§2.3)</source>
            <translation>Comparació de la suavitat (§2.3)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="397" />
            <source>Bézier, degree %1</source>
            <translation>Bézier, grau %1</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="397" />
            <source>C^∞: one polynomial</source>
            <translation>C^∞: un sol polinomi</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="398" />
            <source>only q0 and q%1</source>
            <translation>només q0 i q%1</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="400" />
            <source>Catmull-Rom, τ = %1</source>
            <translation>Catmull-Rom, τ = %1</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="401" />
            <source>C^%1 at the joins (checked)</source>
            <translation>C^%1 a les unions (comprovat)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="402" />
            <source>not C¹ at the joins (checked)</source>
            <translation>no és C¹ a les unions (comprovat)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="403" />
            <location filename="../ui/catmull_rom_report.cpp" line="407" />
            <source>every point</source>
            <translation>tots els punts</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="405" />
            <source>Cubic spline</source>
            <translation>Spline cúbic</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="406" />
            <source>C² (checked above)</source>
            <translation>C² (comprovat més amunt)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="406" />
            <source>not defined</source>
            <translation>no definit</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="408" />
            <source>curve</source>
            <translation>corba</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="408" />
            <source>smoothness</source>
            <translation>suavitat</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="408" />
            <source>passes through</source>
            <translation>passa per</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="410" />
            <source>The Bézier curve only approaches the inner points: Catmull-Rom passes through all of them, which is why the thesis chose it for the frog (§2.3, §4.12).</source>
            <translation>La corba de Bézier només s'acosta als punts interiors: la de Catmull-Rom passa per tots, i per això la tesi la va triar per a la granota (§2.3, §4.12).</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>broken</source>
            <translation>trencada</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>At every knot at least C^%1 and G^%2 (of %n knots).</source>
            <translation>
                <numerusform>A cada nus, almenys C^%1 i G^%2 (d'%n nus).</numerusform>
                <numerusform>A cada nus, almenys C^%1 i G^%2 (de %n nusos).</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>undefined: p′ = 0</source>
            <translation>no definida: p′ = 0</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>the tangent turns by %1°</source>
            <translation>la tangent gira %1°</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>C order</source>
            <translation>ordre C</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>G order</source>
            <translation>ordre G</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>jump</source>
            <translation>salt</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>curvature κ left → right</source>
            <translation>curvatura κ esquerra → dreta</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>… and %n more knots.</source>
            <translation>
                <numerusform>… i %n nus més.</numerusform>
                <numerusform>… i %n nusos més.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>Bézier segments and the knots (§2.3)</source>
            <translation>Segments de Bézier i els nusos (§2.3)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>Each segment as a cubic Bézier curve: b0 = p(0), b1 = b0 + p′(0)/3, b2 = b3 − p′(1)/3, b3 = p(1); for Def 2.8, b1 = p1 + τ(p2 − p0)/3 and b2 = p2 − τ(p3 − p1)/3. Cᵏ: equal derivatives up to order k at the knot; Gᵏ: the same tangent direction (G¹) and curvature (G²).</source>
            <translation>Cada segment com una corba de Bézier cúbica: b0 = p(0), b1 = b0 + p′(0)/3, b2 = b3 − p′(1)/3, b3 = p(1); per a la Def. 2.8, b1 = p1 + τ(p2 − p0)/3 i b2 = p2 − τ(p3 − p1)/3. Cᵏ: derivades iguals fins a l'ordre k al nus; Gᵏ: la mateixa direcció tangent (G¹) i la mateixa curvatura (G²).</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>Centripetal and chordal spacing: the derivatives are taken in the knot parameter u, in which segment i has length hᵢ = |qᵢ₊₁ − qᵢ|ᵅ. There the curve is C¹; in the local parameters the tangents are only parallel (G¹).</source>
            <translation>Espaiat centrípet i de corda: les derivades es prenen en el paràmetre dels nusos u, en què el segment i té longitud hᵢ = |qᵢ₊₁ − qᵢ|ᵅ. En aquest paràmetre la corba és C¹; en els paràmetres locals les tangents només són paral·leles (G¹).</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>Cubic spline C² (Def 2.3)</source>
            <translation>Spline cúbic C² (Def. 2.3)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_report.cpp" line="1" />
            <source>Its graph (x, s(x)) piece by piece, x = xᵢ + hᵢ u, u ∈ [0, 1]; the derivatives in x.</source>
            <translation>El seu gràfic (x, s(x)) tros a tros, x = xᵢ + hᵢ u, u ∈ [0, 1]; les derivades en x.</translation>
        </message>
        <message>
            <source>Cubic spline C² (Def 2.3), %1</source>
            <translation>Spline cúbic C² (Def. 2.3), %1</translation>
        </message>
        <message>
            <source>natural ends</source>
            <translation>extrems naturals</translation>
        </message>
        <message>
            <source>clamped ends</source>
            <translation>extrems subjectes</translation>
        </message>
        <message>
            <source>not-a-knot ends</source>
            <translation>extrems sense nus (not-a-knot)</translation>
        </message>
        <message>
            <source>the ends of Ex 2.1</source>
            <translation>els extrems de l&apos;Ex. 2.1</translation>
        </message>
        <message>
            <source>With Ex 2.1&apos;s ends — s₁‴ = 0 (s₁ is a parabola) and no x² term in s₃ — the pieces above are exactly the corrected ones (docs/thesis-errata.md).</source>
            <translation>Amb els extrems de l&apos;Ex. 2.1 — s₁‴ = 0 (s₁ és una paràbola) i cap terme en x² a s₃ — els trossos de dalt són exactament els corregits (docs/thesis-errata.md).</translation>
        </message>
        <message>
            <source>Ex 2.1&apos;s spline is a cubic spline (Def 2.3) but not the natural one: s″ ≠ 0 at its ends, so its pieces differ from those above. Choose the ends “As Ex 2.1” to get them.</source>
            <translation>L&apos;spline de l&apos;Ex. 2.1 és un spline cúbic (Def. 2.3) però no el natural: s″ ≠ 0 als extrems, i per això els seus trossos difereixen dels de dalt. Trieu els extrems «Com a l&apos;Ex. 2.1» per obtenir-les.</translation>
        </message>
        <message>
            <source>With Ex 2.1&apos;s ends — s₁‴ = 0 (s₁ is a parabola) and no x² term in s₃ — the pieces above are exactly the corrected ones (docs/thesis-errata.md, “Ex 2.1”).</source>
            <translation>Amb els extrems de l&apos;Ex. 2.1 — s₁‴ = 0 (s₁ és una paràbola) i cap terme en x² a s₃ — els trossos de dalt són exactament els corregits (docs/thesis-errata.md, «Ex 2.1»).</translation>
        </message>
        <message>
            <source>Ex 2.1&apos;s spline is a cubic spline (Def 2.3) but not the natural one: s″ ≠ 0 at its ends, so its pieces differ from those above. Choose the ends “As Ex 2.1” to get them (docs/thesis-errata.md, “Ex 2.1”).</source>
            <translation>L&apos;spline de l&apos;Ex. 2.1 és un spline cúbic (Def. 2.3) però no el natural: s″ ≠ 0 als extrems, i per això els seus trossos difereixen dels de dalt. Trieu els extrems «Com a l&apos;Ex. 2.1» per obtenir-los (docs/thesis-errata.md, «Ex 2.1»).</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::BernsteinTab</name>
        <message>
            <source>Ex %1: the curve written in the Bernstein basis is in the panel on the right. Its control points are now the De Casteljau tab's too (Ctrl+Z on either tab gives the old ones back).</source>
            <translation>Ex %1: la corba escrita en la base de Bernstein és al quadre de la dreta. Els seus punts de control ara també són els de la pestanya De Casteljau (Ctrl+Z en qualsevol de les dues torna els anteriors).</translation>
        </message>
        <message>
            <source>Degree n = %1</source>
            <translation>Grau n = %1</translation>
        </message>
        <message>
            <source>Move t</source>
            <translation>Mou t</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="326" />
            <source>At t = %1 the weights sum to %2.&lt;br&gt;Def 2.6: %3 = %4&lt;br&gt;De Casteljau: %5 = %6 (difference %7)</source>
            <translation>A t = %1 els pesos sumen %2.&lt;br&gt;Def 2.6: %3 = %4&lt;br&gt;De Casteljau: %5 = %6 (diferència %7)</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/bernstein_tab.cpp" line="332" />
            <source>Weights of the %n control points of the De Casteljau tab at t (Def 2.6)</source>
            <translation>
                <numerusform>Pesos dels %n punts de control de la pestanya De Casteljau a t (Def 2.6)</numerusform>
                <numerusform>Pesos dels %n punts de control de la pestanya De Casteljau a t (Def 2.6)</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="393" />
            <source>yes</source>
            <translation>sí</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="395" />
            <source>%1 %2 %3 — residual at t: %4; exact as polynomials: %5</source>
            <translation>%1 %2 %3 — residu a t: %4; exacta com a polinomis: %5</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="397" />
            <source>no</source>
            <translation>no</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="399" />
            <source>Partition of unity:</source>
            <translation>Partició de la unitat:</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="402" />
            <source>Symmetry:</source>
            <translation>Simetria:</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="407" />
            <source>Recursion (Lemma 2.1):</source>
            <translation>Recurrència (Lema 2.1):</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="414" />
            <source>Recursion (Lemma 2.1): needs n ≥ 1.</source>
            <translation>Recurrència (Lema 2.1): cal n ≥ 1.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="429" />
            <source>Bernstein polynomials of degree %1 (Def 2.5)</source>
            <translation>Polinomis de Bernstein de grau %1 (Def 2.5)</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="440" />
            <source>The De Casteljau tab's curve in the Bernstein basis (Def 2.6)</source>
            <translation>La corba de la pestanya De Casteljau en la base de Bernstein (Def 2.6)</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="443" />
            <source>The control points are not small fractions, so the curve is not expanded exactly.</source>
            <translation>Els punts de control no són fraccions petites; per això la corba no es desenvolupa exactament.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="445" />
            <source>The expansion is shown up to degree %1; the curve has degree %2.</source>
            <translation>El desenvolupament es mostra fins al grau %1; la corba té grau %2.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="468" />
            <source>Degree n:</source>
            <translation>Grau n:</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="469" />
            <source>The degree n of the Bernstein polynomials Bᵢⁿ(t) = C(n,i) tⁱ (1−t)ⁿ⁻ⁱ (Def 2.5).</source>
            <translation>El grau n dels polinomis de Bernstein Bᵢⁿ(t) = C(n,i) tⁱ (1−t)ⁿ⁻ⁱ (Def 2.5).</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="472" />
            <source>All degrees up to n</source>
            <translation>Tots els graus fins a n</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="473" />
            <source>Overlay the polynomials of every degree 0…n, one colour per degree, like the tots option of the thesis's Matlab Rep_Pol_Bernstein (Ex 2.4, Figure 2.4).</source>
            <translation>Superposa els polinomis de cada grau 0…n, un color per grau, com l'opció tots de la funció de Matlab Rep_Pol_Bernstein de la tesi (Ex 2.4, Figura 2.4).</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="475" />
            <source>value</source>
            <translation>valor</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="476" />
            <source>The Bernstein polynomials on [0, 1] (Def 2.5). Move the mouse to read their values; click or drag to move t, shared with the De Casteljau tab.</source>
            <translation>Els polinomis de Bernstein a [0, 1] (Def 2.5). Moveu el ratolí per llegir-ne els valors; feu clic o arrossegueu per moure t, compartit amb la pestanya De Casteljau.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="478" />
            <source>Def 2.6: c(t) = Σ Bᵢⁿ(t) Pᵢ. Each bar is the weight of one control point of the De Casteljau tab at the current t; they sum to 1 (partition of unity).</source>
            <translation>Def 2.6: c(t) = Σ Bᵢⁿ(t) Pᵢ. Cada barra és el pes d'un punt de control de la pestanya De Casteljau al t actual; sumen 1 (partició de la unitat).</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="480" />
            <source>weight</source>
            <translation>pes</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="481" />
            <source>The point c(t) from the Bernstein sum (Def 2.6) and from De Casteljau's algorithm (Def 2.4): equal by Prop 2.1.</source>
            <translation>El punt c(t) obtingut amb la suma de Bernstein (Def 2.6) i amb l'algorisme de De Casteljau (Def 2.4): iguals per la Prop 2.1.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="483" />
            <source>Properties at the current n and t</source>
            <translation>Propietats als n i t actuals</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="484" />
            <source>Each property is checked twice: in floating point at t (the residual) and exactly, as polynomials with rational coefficients.</source>
            <translation>Cada propietat es comprova dues vegades: en coma flotant a t (el residu) i exactament, com a polinomis de coeficients racionals.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="486" />
            <source>Partition of unity: the Bernstein polynomials of one degree sum to 1.</source>
            <translation>Partició de la unitat: els polinomis de Bernstein d'un mateix grau sumen 1.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="487" />
            <source>Symmetry: Bᵢⁿ(t) = Bₙ₋ᵢⁿ(1 − t).</source>
            <translation>Simetria: Bᵢⁿ(t) = Bₙ₋ᵢⁿ(1 − t).</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="488" />
            <source>Lemma 2.1: Bᵢⁿ = (1 − t) Bᵢⁿ⁻¹ + t Bᵢ₋₁ⁿ⁻¹.</source>
            <translation>Lema 2.1: Bᵢⁿ = (1 − t) Bᵢⁿ⁻¹ + t Bᵢ₋₁ⁿ⁻¹.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="489" />
            <source>The Bernstein polynomials expanded in powers of t (Ex 2.4) and the De Casteljau tab's curve written in the Bernstein basis (Ex 2.5, Ex 2.6).</source>
            <translation>Els polinomis de Bernstein desenvolupats en potències de t (Ex 2.4) i la corba de la pestanya De Casteljau escrita en la base de Bernstein (Ex 2.5, Ex 2.6).</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="517" />
            <source>The Bernstein degree must be a whole number from 0 to %1.</source>
            <translation>El grau de Bernstein ha de ser un nombre enter de 0 a %1.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="523" />
            <source>The Bernstein mode must be "single" or "all".</source>
            <translation>El mode de Bernstein ha de ser "single" o "all".</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="529" />
            <source>The parameter t must be a number between 0 and 1.</source>
            <translation>El paràmetre t ha de ser un nombre entre 0 i 1.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="546" />
            <source>Ex %1: the Bernstein polynomials of every degree up to %2.</source>
            <translation>Ex %1: els polinomis de Bernstein de cada grau fins a %2.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="552" />
            <source>Load Ex %1</source>
            <translation>Carrega l'Ex %1</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="557" />
            <source>Ex %1: the curve written in the Bernstein basis is in the panel on the right.</source>
            <translation>Ex %1: la corba escrita en la base de Bernstein és al quadre de la dreta.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.cpp" line="613" />
            <source>Move the mouse over the plot to read Bᵢⁿ(t); click or drag to move t.</source>
            <translation>Moveu el ratolí per sobre del gràfic per llegir Bᵢⁿ(t); feu clic o arrossegueu per moure t.</translation>
        </message>
        <message>
            <location filename="../ui/bernstein_tab.h" line="46" />
            <source>Bernstein</source>
            <translation>Bernstein</translation>
        </message>
        <message>
            <source>Mark t</source>
            <translation>Marca t</translation>
        </message>
        <message>
            <source>Hide the mark at t</source>
            <translation>Amaga la marca a t</translation>
        </message>
        <message>
            <source>The dashed vertical line at the current t, shared with the De Casteljau tab. Off, the plot and its exports show the polynomials alone, as Figure 2.4 does.</source>
            <translation>La línia vertical discontínua a la t actual, compartida amb la pestanya De Casteljau. Desactivada, el gràfic i les seves exportacions mostren només els polinomis, com la Figura 2.4.</translation>
        </message>
        <message>
            <source>The Bernstein tab&apos;s “t_marker” must be true or false.</source>
            <translation>El «t_marker» de la pestanya Bernstein ha de ser cert o fals.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::CatmullRomTab</name>
        <message>
            <source>Exact results and points</source>
            <translation>Resultats exactes i punts</translation>
        </message>
        <message>
            <source>Tensions τ</source>
            <translation>Tensions τ</translation>
        </message>
        <message>
            <source>none</source>
            <translation>cap</translation>
        </message>
        <message numerus="yes">
            <source>Catmull-Rom curves through %n point(s), tensions τ = %1.</source>
            <translation>
                <numerusform>Corbes de Catmull-Rom per %n punt, tensions τ = %1.</numerusform>
                <numerusform>Corbes de Catmull-Rom per %n punts, tensions τ = %1.</numerusform>
            </translation>
        </message>
        <message>
            <source>Catmull-Rom canvas</source>
            <translation>Llenç de Catmull-Rom</translation>
        </message>
        <message>
            <source>Drag a point; double-click to add one; pick a τ in the list and move its slider, or type one and press Enter.</source>
            <translation>Arrossegueu un punt; doble clic n’afegeix un; trieu una τ a la llista i moveu-ne el control, o escriviu-ne una i premeu Retorn.</translation>
        </message>
        <message>
            <source>Select τ = %1</source>
            <translation>Tria τ = %1</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="286" />
            <source>Tensions τ (Def 2.8)</source>
            <translation>Tensions τ (Def. 2.8)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="287" />
            <source>The tension τ scales the tangents p′(0) = τ(p2 − p0), p′(1) = τ(p3 − p1) of every segment (Def 2.8): 0 gives straight segments, 1/2 is the usual value, negative values turn the tangents round (Ex 2.12). One curve per τ, in its colour.</source>
            <translation>La tensió τ escala les tangents p′(0) = τ(p2 − p0), p′(1) = τ(p3 − p1) de cada segment (Def. 2.8): 0 dona segments rectes, 1/2 és el valor habitual i els valors negatius giren les tangents (Ex. 2.12). Una corba per cada τ, amb el seu color.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="290" />
            <source>The tensions drawn, each with its colour and Processing's curveTightness(s), τ = (1 − s)/2. Select one for the slider, the blending plot and the tangent table.</source>
            <translation>Les tensions dibuixades, cadascuna amb el seu color i el curveTightness(s) de Processing, τ = (1 − s)/2. Seleccioneu-ne una per al control lliscant, el gràfic de les funcions de mescla i la taula de tangents.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="292" />
            <source>τ, e.g. 1/2 or -0.5</source>
            <translation>τ, p. ex. 1/2 o -0,5</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="293" />
            <source>Type a tension as a decimal or a fraction (-1/2), between −10 and 10, and press Enter.</source>
            <translation>Escriviu una tensió com a decimal o com a fracció (-1/2), entre −10 i 10, i premeu Retorn.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="294" />
            <source>&amp;Add</source>
            <translation>&amp;Afegeix</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="295" />
            <source>Add the typed tension: one more curve on the canvas (Ex 2.11 compares 0, 1/2 and 2).</source>
            <translation>Afegeix la tensió escrita: una corba més al llenç (l'Ex. 2.11 compara 0, 1/2 i 2).</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="296" />
            <source>&amp;Remove</source>
            <translation>&amp;Elimina</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="297" />
            <source>Remove the selected tension and its curve.</source>
            <translation>Elimina la tensió seleccionada i la seua corba.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="298" />
            <source>Drag to change the selected tension in steps of 0.05, from −10 to 10; the curve, the blending functions and the exact panel follow.</source>
            <translation>Arrossegueu per canviar la tensió seleccionada en passos de 0,05, de −10 a 10; la corba, les funcions de mescla i el quadre exacte la segueixen.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="300" />
            <source>Curve (Def 2.10)</source>
            <translation>Corba (Def. 2.10)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="301" />
            <source>&amp;Ends:</source>
            <translation>E&amp;xtrems:</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="302" />
            <source>open (ends repeated)</source>
            <translation>oberta (extrems repetits)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="303" />
            <source>cyclic (n segments)</source>
            <translation>cíclica (n segments)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="304" />
            <source>closed (n + 1 segments)</source>
            <translation>tancada (n+1 segments)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="305" />
            <source>single segment (Def 2.8)</source>
            <translation>un sol segment (Def. 2.8)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="306" />
            <source>How the end segments get their missing neighbours (Def 2.10, Matlab Rep_CatmullRom): open repeats q0 and qn (p1′(0) = τ(q1 − q0)); cyclic takes q₋₁ = qn and qn₊₁ = q0 (n segments, Ex 2.13); closed adds the segment from qn back to q0; a single segment (Def 2.8, Ex 2.11) keeps only the segments with both neighbours.</source>
            <translation>Com obtenen els segments extrems els veïns que els falten (Def. 2.10, Rep_CatmullRom de Matlab): l'oberta repeteix q0 i qn (p1′(0) = τ(q1 − q0)); la cíclica pren q₋₁ = qn i qn₊₁ = q0 (n segments, Ex. 2.13); la tancada afegeix el segment de qn a q0; un sol segment (Def. 2.8, Ex. 2.11) només conserva els segments que tenen tots dos veïns.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="310" />
            <source>&amp;Parametrization:</source>
            <translation>&amp;Parametrització:</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="311" />
            <source>uniform (thesis)</source>
            <translation>uniforme (tesi)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="312" />
            <source>centripetal (α = 1/2)</source>
            <translation>centrípeta (α = 1/2)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="313" />
            <source>chordal (α = 1)</source>
            <translation>de corda (α = 1)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="314" />
            <source>Knot spacing |qᵢ₊₁ − qᵢ|ᵅ. The thesis uses uniform spacing (α = 0). Beyond it: centripetal (α = 1/2) avoids cusps and loops, chordal (α = 1) follows the chord lengths; the segments then join with parallel tangents (G¹).</source>
            <translation>Separació dels nusos |qᵢ₊₁ − qᵢ|ᵅ. La tesi fa servir la parametrització uniforme (α = 0). Més enllà: la centrípeta (α = 1/2) evita cúspides i bucles, la de longitud de corda (α = 1) segueix les longituds de les cordes; aleshores els segments s'uneixen amb tangents paral·leles (G¹).</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="317" />
            <source>Compare with &amp;Bézier</source>
            <translation>Compara amb &amp;Bézier</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="318" />
            <source>Draw the Bézier curve that has the same points as control polygon (De Casteljau, Def 2.4): it passes only through q0 and qn, while Catmull-Rom passes through every point (§2.3).</source>
            <translation>Dibuixa la corba de Bézier que té els mateixos punts com a polígon de control (De Casteljau, Def. 2.4): només passa per q0 i qn, mentre que la de Catmull-Rom passa per tots els punts (§2.3).</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="321" />
            <source>Cubic &amp;spline (C²)</source>
            <translation>&amp;Spline cúbic (C²)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="322" />
            <source>Draw the C² cubic spline of Def 2.3 through the same points, with the ends chosen below (a function of x: the abscissae must increase), and check its continuity at the knots: Bézier C^∞, Catmull-Rom C¹, cubic spline C² (§2.3, Ex 2.1).</source>
            <translation>Dibuixa l'spline cúbic C² de la Def. 2.3 pels mateixos punts, amb els extrems triats a sota (una funció de x: les abscisses han de créixer), i comprova'n la continuïtat als nusos: Bézier C^∞, Catmull-Rom C¹, spline cúbic C² (§2.3, Ex. 2.1).</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="325" />
            <source>Compare open and &amp;cyclic ends</source>
            <translation>Compara els extrems oberts i &amp;cíclics</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="326" />
            <source>Also draw (dashed) and list the curve with the other end mode, as Ex 2.13 compares the cyclic and the open curve through the same points.</source>
            <translation>Dibuixa també (discontínua) i llista la corba amb l'altre tipus d'extrems, com l'Ex. 2.13 compara la corba cíclica i l'oberta pels mateixos punts.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="328" />
            <source>Blending functions wⱼ(t, τ) (Def 2.9, Cor 2.1)</source>
            <translation>Funcions de mescla wⱼ(t, τ) (Def. 2.9, Cor. 2.1)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="329" />
            <source>p(t) = Σ wⱼ(t, τ) pⱼ: the weight of each of the four points along a segment. They always add up to 1.</source>
            <translation>p(t) = Σ wⱼ(t, τ) pⱼ: el pes de cadascun dels quatre punts al llarg d'un segment. Sempre sumen 1.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="331" />
            <source>Every &amp;τ</source>
            <translation>Totes les &amp;τ</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="332" />
            <source>Plot the blending functions of every tension in the list (one line style per τ), as Ex 2.12 does for τ = −2, 0, 1/2 and 2.</source>
            <translation>Representa les funcions de mescla de totes les tensions de la llista (un estil de línia per τ), com fa l'Ex. 2.12 per a τ = −2, 0, 1/2 i 2.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="334" />
            <source>The blending functions w₀…w₃ of Cor 2.1 on t ∈ [0, 1].</source>
            <translation>Les funcions de mescla w₀…w₃ del Cor. 2.1 en t ∈ [0, 1].</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="335" />
            <source>Exact results: segment polynomials (Lemma 2.3, Def 2.10), tangents at the knots (Prop 2.3), blending functions (Cor 2.1), and the comparisons of §2.3.</source>
            <translation>Resultats exactes: polinomis dels segments (Lema 2.3, Def. 2.10), tangents als nusos (Prop. 2.3), funcions de mescla (Cor. 2.1) i les comparacions de la §2.3.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="337" />
            <source>Drag a point to move it; double-click to add one; Delete removes the selected point; drag the paper to pan, wheel to zoom.</source>
            <translation>Arrossegueu un punt per moure'l; feu doble clic per afegir-ne un; Supr elimina el punt seleccionat; arrossegueu el paper per desplaçar la vista i feu servir la roda per fer zoom.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="339" />
            <source>Exact results</source>
            <translation>Resultats exactes</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="340" />
            <source>Points</source>
            <translation>Punts</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="342" />
            <source>The points q0…qn as numbers; fractions such as 1/3 are accepted.</source>
            <translation>Els punts q0…qn com a nombres; s'accepten fraccions com 1/3.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="350" />
            <source>τ = %1   (curveTightness %2)</source>
            <translation>τ = %1   (curveTightness de Processing: %2)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="376" />
            <source>Selected: τ = %1, Processing's curveTightness(%2)</source>
            <translation>Seleccionada: τ = %1, curveTightness(%2) de Processing</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="420" />
            <source>τ = %1 is outside [−10, 10]: beyond that the curve is all overshoot. Not added.</source>
            <translation>τ = %1 és fora de [−10, 10]: més enllà la corba només fa sobreoscil·lacions. No s'ha afegit.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="423" />
            <source>“%1” is not a tension: type a decimal (0.5) or a fraction (-1/2). Not added.</source>
            <translation>«%1» no és una tensió: escriviu un decimal (0,5) o una fracció (-1/2). No s'ha afegit.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="427" />
            <location filename="../ui/catmull_rom_tab.cpp" line="476" />
            <source>τ = %1 is already in the list.</source>
            <translation>τ = %1 ja és a la llista.</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/catmull_rom_tab.cpp" line="431" />
            <source>At most %n tensions at a time: remove one first.</source>
            <translation>
                <numerusform>Com a màxim %n tensions alhora: primer elimineu-ne una.</numerusform>
                <numerusform>Com a màxim %n tensions alhora: primer elimineu-ne una.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="437" />
            <source>Add τ = %1</source>
            <translation>Afegeix τ = %1</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="438" />
            <source>Added τ = %1.</source>
            <translation>S'ha afegit τ = %1.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="447" />
            <source>At least one tension is needed.</source>
            <translation>Cal almenys una tensió.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="454" />
            <source>Remove τ = %1</source>
            <translation>Elimina τ = %1</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="482" />
            <source>Change τ</source>
            <translation>Canvia τ</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="489" />
            <source>Change the ends</source>
            <translation>Canvia els extrems</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="491" />
            <source>A single segment uses four points p0…p3 and joins p1 to p2; with more points, every segment that has both neighbours is drawn.</source>
            <translation>Un sol segment fa servir quatre punts p0…p3 i uneix p1 amb p2; amb més punts, es dibuixen tots els segments que tenen tots dos veïns.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="499" />
            <source>Change the parametrization</source>
            <translation>Canvia la parametrització</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="506" />
            <source>Show the Bézier curve</source>
            <translation>Mostra la corba de Bézier</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="506" />
            <source>Hide the Bézier curve</source>
            <translation>Amaga la corba de Bézier</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="513" />
            <source>Show the cubic spline</source>
            <translation>Mostra l'spline cúbic</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="513" />
            <source>Hide the cubic spline</source>
            <translation>Amaga l'spline cúbic</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="520" />
            <source>Compare the ends</source>
            <translation>Compara els extrems</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="527" />
            <source>Blending functions of every τ</source>
            <translation>Funcions de mescla de totes les τ</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="689" />
            <source>dashed: %1 ends</source>
            <translation>discontínua: la corba %1</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="691" />
            <source>Bézier curve of the same points</source>
            <translation>Corba de Bézier dels mateixos punts</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="694" />
            <source>no cubic spline: x must increase</source>
            <translation>sense spline cúbic: x ha de créixer</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="694" />
            <source>cubic spline C²</source>
            <translation>spline cúbic C²</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="796" />
            <location filename="../ui/catmull_rom_tab.cpp" line="798" />
            <location filename="../ui/catmull_rom_tab.cpp" line="799" />
            <source>Load Ex %1</source>
            <translation>Carrega l'Ex %1</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="826" />
            <source>The Catmull-Rom points are missing or not a list.</source>
            <translation>Els punts de Catmull-Rom falten o no són una llista.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="829" />
            <source>A Catmull-Rom curve needs between 2 and %1 points; the file has %2.</source>
            <translation>Una corba de Catmull-Rom necessita entre 2 i %1 punts; el fitxer en té %2.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="836" />
            <source>Point %1 of the Catmull-Rom tab is not a pair of numbers.</source>
            <translation>El punt %1 de la pestanya Catmull-Rom no és un parell de nombres.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="839" />
            <source>Point %1 of the Catmull-Rom tab is not a finite number.</source>
            <translation>El punt %1 de la pestanya Catmull-Rom no és un nombre finit.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="845" />
            <source>The Catmull-Rom settings are not valid (“%1”): tensions must be numbers in [−10, 10], at most %2 of them, without repeats.</source>
            <translation>La configuració de Catmull-Rom no és vàlida («%1»): les tensions han de ser nombres de [−10, 10], com a màxim %2, sense repeticions.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.h" line="42" />
            <source>Catmull-Rom</source>
            <translation>Catmull-Rom</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="1" />
            <source>C&amp;urvature κ(s) in the plot</source>
            <translation>C&amp;urvatura κ(s) al gràfic</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="1" />
            <source>Plot the signed curvature κ of every curve on the canvas against its arc length s instead of the blending functions: κ jumps at the knots of a Catmull-Rom curve (C¹, not C²) and is continuous along the C² cubic spline (§2.3).</source>
            <translation>Dibuixa la curvatura amb signe κ de cada corba del llenç en funció de la seva longitud d'arc s, en lloc de les funcions de mescla: κ salta als nusos d'una corba de Catmull-Rom (C¹, no C²) i és contínua al llarg de l'spline cúbic C² (§2.3).</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="1" />
            <source>Curvature κ against arc length s (§2.3)</source>
            <translation>Curvatura κ segons la longitud d'arc s (§2.3)</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="1" />
            <source>κ = (x′y″ − y′x″)/|p′|³, positive where the curve turns left. A Catmull-Rom curve is C¹ but not C²: p″ jumps at its knots and so does κ (a break in the line). The C² cubic spline's κ is continuous, and the Bézier curve is one polynomial (C^∞).</source>
            <translation>κ = (x′y″ − y′x″)/|p′|³, positiva on la corba gira a l'esquerra. Una corba de Catmull-Rom és C¹ però no C²: p″ salta als seus nusos i κ també (un tall a la línia). La κ de l'spline cúbic C² és contínua, i la corba de Bézier és un sol polinomi (C^∞).</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="1" />
            <source>κ(s) of every curve drawn, in its colour and line style as on the canvas; the light vertical lines are the knots of the selected τ.</source>
            <translation>κ(s) de cada corba dibuixada, amb el color i el traç del llenç; les línies verticals clares són els nusos de la τ seleccionada.</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="1" />
            <source>Plot the curvature</source>
            <translation>Mostra la curvatura</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="1" />
            <source>Plot the blending functions</source>
            <translation>Mostra les funcions de mescla</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="1" />
            <source>arc length s</source>
            <translation>longitud d'arc s</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="1" />
            <source>curvature κ</source>
            <translation>curvatura κ</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="1" />
            <source>τ = %1, %2 ends</source>
            <translation>τ = %1, corba %2</translation>
        </message>
        <message>
            <location filename="../ui/catmull_rom_tab.cpp" line="1" />
            <source>Bézier</source>
            <translation>Bézier</translation>
        </message>
        <message>
            <source>An end slope is a number between −10 and 10, such as 1/2 or -0.25.</source>
            <translation>Un pendent d&apos;extrem és un nombre entre −10 i 10, com ara 1/2 o -0,25.</translation>
        </message>
        <message>
            <source>Cat&amp;mull-Rom curves</source>
            <translation>Corbes de Catmull-&amp;Rom</translation>
        </message>
        <message>
            <source>Draw the Catmull-Rom curve of each tension. Hide them to see the cubic spline alone, as Fig 2.1 shows Ex 2.1&apos;s.</source>
            <translation>Dibuixa la corba de Catmull-Rom de cada tensió. Amaga-les per veure l&apos;spline cúbic tot sol, com la Fig. 2.1 mostra el de l&apos;Ex. 2.1.</translation>
        </message>
        <message>
            <source>Spline e&amp;nds:</source>
            <translation>Extrems de l&apos;spli&amp;ne:</translation>
        </message>
        <message>
            <source>Natural (s″ = 0)</source>
            <translation>Naturals (s″ = 0)</translation>
        </message>
        <message>
            <source>Clamped (slopes)</source>
            <translation>Subjectes</translation>
        </message>
        <message>
            <source>Not-a-knot</source>
            <translation>Sense nus</translation>
        </message>
        <message>
            <source>As Ex 2.1</source>
            <translation>Com a l&apos;Ex. 2.1</translation>
        </message>
        <message>
            <source>Def 2.3 leaves two degrees of freedom; the ends fix them. Natural: s″ = 0 at both ends. Clamped: the end slopes are given. Not-a-knot: the first two pieces are one cubic, and so are the last two. As Ex 2.1: the first piece is a parabola (s₁‴ = 0) and the last has no x² term — the ends that give Ex 2.1&apos;s pieces.</source>
            <translation>La Def. 2.3 deixa dos graus de llibertat; els extrems els fixen. Naturals: s″ = 0 a tots dos extrems. Subjectes: es donen els pendents als extrems. Sense nus: els dos primers trossos són una sola cúbica, i també els dos últims. Com a l&apos;Ex. 2.1: el primer tros és una paràbola (s₁‴ = 0) i l&apos;últim no té terme en x² — els extrems que donen els trossos de l&apos;Ex. 2.1.</translation>
        </message>
        <message>
            <source>End s&amp;lopes:</source>
            <translation>Pen&amp;dents:</translation>
        </message>
        <message>
            <source>s′(x₀), the slope at the first point (clamped ends)</source>
            <translation>s′(x₀), el pendent al primer punt (extrems subjectes)</translation>
        </message>
        <message>
            <source>s′(xₖ), the slope at the last point (clamped ends)</source>
            <translation>s′(xₖ), el pendent a l&apos;últim punt (extrems subjectes)</translation>
        </message>
        <message>
            <source>Change the spline&apos;s ends</source>
            <translation>Canvia els extrems de l&apos;spline</translation>
        </message>
        <message>
            <source>Change the spline&apos;s end slopes</source>
            <translation>Canvia els pendents dels extrems de l&apos;spline</translation>
        </message>
        <message>
            <source>Show the Catmull-Rom curves</source>
            <translation>Mostra les corbes de Catmull-Rom</translation>
        </message>
        <message>
            <source>Hide the Catmull-Rom curves</source>
            <translation>Amaga les corbes de Catmull-Rom</translation>
        </message>
        <message>
            <source>Poin&amp;ts</source>
            <translation>Pun&amp;ts</translation>
        </message>
        <message>
            <source>Draw the points qᵢ that the curves interpolate, their labels and their polygon; off, the curves alone, like puntvis = false in the thesis&apos;s Matlab Rep_CatmullRom. The table still edits the points.</source>
            <translation>Dibuixa els punts qᵢ que interpolen les corbes, les seves etiquetes i el seu polígon; desactivat, només les corbes, com puntvis = false al Rep_CatmullRom del Matlab de la tesi. La taula continua editant els punts.</translation>
        </message>
        <message>
            <source>Show the points</source>
            <translation>Mostra els punts</translation>
        </message>
        <message>
            <source>Hide the points</source>
            <translation>Amaga els punts</translation>
        </message>
        <message>
            <source>Back to the Catmull-Rom tangents</source>
            <translation>Torna a les tangents de Catmull-Rom</translation>
        </message>
        <message>
            <source>Change B</source>
            <translation>Canvia B</translation>
        </message>
        <message>
            <source>Change C</source>
            <translation>Canvia C</translation>
        </message>
        <message>
            <source>Change T</source>
            <translation>Canvia T</translation>
        </message>
        <message>
            <source>Change the cardinal tension</source>
            <translation>Canvia la tensió cardinal</translation>
        </message>
        <message>
            <source>Conventions</source>
            <translation>Convencions</translation>
        </message>
        <message>
            <source>Drag the tangent at q%1</source>
            <translation>Arrossega la tangent a q%1</translation>
        </message>
        <message>
            <source>Family: %1</source>
            <translation>Família: %1</translation>
        </message>
        <message>
            <source>Knots</source>
            <translation>Nusos</translation>
        </message>
        <message>
            <source>Move the tangent at q%1</source>
            <translation>Mou la tangent a q%1</translation>
        </message>
        <message>
            <source>tangent in (p′(1)), where it differs</source>
            <translation>tangent d&apos;entrada (p′(1)), on és diferent</translation>
        </message>
        <message>
            <source>tangent out (p′(0))</source>
            <translation>tangent de sortida (p′(0))</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::DeCasteljauParameterControl</name>
        <message>
            <source>Parameter t</source>
            <translation>Paràmetre t</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_parameter_control.cpp" line="95" />
            <source>The parameter t ∈ [0, 1] of the curve c(t) (Def 2.4). Type a decimal or a fraction such as 1/3.</source>
            <translation>El paràmetre t ∈ [0, 1] de la corba c(t) (Def 2.4). Escriviu un decimal o una fracció com ara 1/3.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::DeCasteljauTab</name>
        <message>
            <source>Comb scale</source>
            <translation>Escala de la pinta</translation>
        </message>
        <message>
            <source>scale:</source>
            <translation>escala:</translation>
        </message>
        <message>
            <source>The comb's scale must be 0 (automatic) or a positive number up to %1.</source>
            <translation>L'escala de la pinta ha de ser 0 (automàtica) o un nombre positiu fins a %1.</translation>
        </message>
        <message>
            <source>The arc length s(t) from c(0) to c(t), the curve's length L, and the signed curvature κ(t) = (x′y″ − y′x″)/|c′|³ (positive when the curve turns left).</source>
            <translation>La longitud d'arc s(t) de c(0) a c(t), la longitud L de la corba i la curvatura amb signe κ(t) = (x′y″ − y′x″)/|c′|³ (positiva quan la corba gira a l'esquerra).</translation>
        </message>
        <message>
            <source>When playing, move c(t) by equal steps of arc length instead of equal steps of t: t is not distance along the curve.</source>
            <translation>En reproduir, mou c(t) per passos iguals de longitud d'arc en lloc de passos iguals de t: t no és la distància al llarg de la corba.</translation>
        </message>
        <message>
            <source>The hodograph c′ in the corner: a Bézier curve of degree n − 1 with control points n (Pᵢ₊₁ − Pᵢ), with its own De Casteljau construction at the same t; its point is c′(t).</source>
            <translation>L'hodògraf c′ a la cantonada: una corba de Bézier de grau n − 1 amb punts de control n (Pᵢ₊₁ − Pᵢ), amb la seva pròpia construcció de De Casteljau al mateix t; el seu punt és c′(t).</translation>
        </message>
        <message>
            <source>Inflection points ○, where x′y″ − y′x″ changes sign (the curve turns the other way), and cusps ×, where c′ = 0.</source>
            <translation>Punts d'inflexió ○, on x′y″ − y′x″ canvia de signe (la corba gira cap a l'altre costat), i cúspides ×, on c′ = 0.</translation>
        </message>
        <message>
            <source>The tight axis-aligned box of the curve (not of its control points), from the extrema of x(t) and y(t): the t where x′ = 0 or y′ = 0, marked ◆.</source>
            <translation>La capsa ajustada de la corba alineada amb els eixos (no la dels seus punts de control), a partir dels extrems de x(t) i y(t): els t on x′ = 0 o y′ = 0, marcats ◆.</translation>
        </message>
        <message>
            <source>Teeth along the normal, as long as |κ| times the scale given in the key, and the line through their tips: where the comb jumps, so does the curvature. No tooth where κ is undefined.</source>
            <translation>Pues al llarg de la normal, tan llargues com |κ| per l'escala que indica la llegenda, i la línia que passa per les seves puntes: on la pinta salta, també salta la curvatura. Cap pua on κ no està definida.</translation>
        </message>
        <message>
            <source>The circle that fits the curve best at c(t): centre c(t) + N(t)/κ(t), radius 1/|κ(t)|. None where κ = 0 (the radius is infinite) or where κ is undefined (c′(t) = 0).</source>
            <translation>La circumferència que millor s'ajusta a la corba a c(t): centre c(t) + N(t)/κ(t), radi 1/|κ(t)|. No n'hi ha on κ = 0 (el radi és infinit) ni on κ no està definida (c′(t) = 0).</translation>
        </message>
        <message>
            <source>The unit normal N(t) at c(t), the tangent turned a quarter turn to the left; drawn as long as the tangent's arrow. Undefined where c′(t) = 0.</source>
            <translation>La normal unitària N(t) a c(t), la tangent girada un quart de volta cap a l'esquerra; dibuixada tan llarga com la fletxa de la tangent. No està definida on c′(t) = 0.</translation>
        </message>
        <message>
            <source>c′(t) = %1, c″(t) = %2&lt;br&gt;x′y″ − y′x″ = %3, |c′(t)|² = %4&lt;br&gt;κ(t) = (x′y″ − y′x″)/|c′|³ = %5 ≈ %6</source>
            <translation>c′(t) = %1, c″(t) = %2&lt;br&gt;x′y″ − y′x″ = %3, |c′(t)|² = %4&lt;br&gt;κ(t) = (x′y″ − y′x″)/|c′|³ = %5 ≈ %6</translation>
        </message>
        <message>
            <source>κ(t) is undefined: c′(t) = 0 (a cusp, or coincident control points), so there is no normal and no osculating circle.</source>
            <translation>κ(t) no està definida: c′(t) = 0 (una cúspide, o punts de control coincidents), de manera que no hi ha normal ni circumferència osculatriu.</translation>
        </message>
        <message>
            <source>s(t) = %1, L = %2</source>
            <translation>s(t) = %1, L = %2</translation>
        </message>
        <message>
            <source>Arc length and curvature at t</source>
            <translation>Longitud d'arc i curvatura a t</translation>
        </message>
        <message>
            <source>κ(t) = %1 (radius %2)</source>
            <translation>κ(t) = %1 (radi %2)</translation>
        </message>
        <message>
            <source>κ(t) = 0: straight here, the radius is infinite</source>
            <translation>κ(t) = 0: aquí és recta, el radi és infinit</translation>
        </message>
        <message>
            <source>κ(t) undefined: c′(t) = 0 (a cusp, or coincident control points)</source>
            <translation>κ(t) no definida: c′(t) = 0 (una cúspide, o punts de control coincidents)</translation>
        </message>
        <message>
            <source>s(t) = %1 of L = %2</source>
            <translation>s(t) = %1 de L = %2</translation>
        </message>
        <message>
            <source>hodograph c′</source>
            <translation>hodògraf c′</translation>
        </message>
        <message>
            <source>○ inflections: %1 · × cusps: %2</source>
            <translation>○ punts d'inflexió: %1 · × cúspides: %2</translation>
        </message>
        <message>
            <source>bounding box, ◆ extrema of x and y</source>
            <translation>capsa contenidora, ◆ extrems de x i de y</translation>
        </message>
        <message>
            <source>curvature comb: teeth |κ| × %1</source>
            <translation>pinta de curvatura: pues |κ| × %1</translation>
        </message>
        <message>
            <source>no osculating circle: κ undefined</source>
            <translation>sense circumferència osculatriu: κ no definida</translation>
        </message>
        <message>
            <source>no osculating circle: κ(t) = 0</source>
            <translation>sense circumferència osculatriu: κ(t) = 0</translation>
        </message>
        <message>
            <source>osculating circle, r = 1/|κ| = %1</source>
            <translation>circumferència osculatriu, r = 1/|κ| = %1</translation>
        </message>
        <message>
            <source>no normal: c′(t) = 0</source>
            <translation>sense normal: c′(t) = 0</translation>
        </message>
        <message>
            <source>unit normal N(t)</source>
            <translation>normal unitària N(t)</translation>
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
            <translation>Velocitat constant</translation>
        </message>
        <message>
            <source>Hodograph</source>
            <translation>Hodògraf</translation>
        </message>
        <message>
            <source>Inflections and cusps</source>
            <translation>Punts d'inflexió i cúspides</translation>
        </message>
        <message>
            <source>Bounding box</source>
            <translation>Capsa contenidora</translation>
        </message>
        <message>
            <source>Curvature comb</source>
            <translation>Pinta de curvatura</translation>
        </message>
        <message>
            <source>Osculating circle</source>
            <translation>Circumferència osculatriu</translation>
        </message>
        <message>
            <source>Normal</source>
            <translation>Vector normal</translation>
        </message>
        <message numerus="yes">
            <source>Bézier curve of degree %1 with %n control point(s); t = %2, c(t) = %3.</source>
            <translation>
                <numerusform>Corba de Bézier de grau %1 amb %n punt de control; t = %2, c(t) = %3.</numerusform>
                <numerusform>Corba de Bézier de grau %1 amb %n punts de control; t = %2, c(t) = %3.</numerusform>
            </translation>
        </message>
        <message>
            <source>No control points.</source>
            <translation>Cap punt de control.</translation>
        </message>
        <message>
            <source>De Casteljau canvas</source>
            <translation>Llenç de De Casteljau</translation>
        </message>
        <message>
            <source>polygon of the half on [t, 1]</source>
            <translation>polígon de la meitat a [t, 1]</translation>
        </message>
        <message>
            <source>polygon of the half on [0, t]</source>
            <translation>polígon de la meitat a [0, t]</translation>
        </message>
        <message>
            <source>… %1 more, one colour each</source>
            <translation>… %1 més, cadascun del seu color</translation>
        </message>
        <message>
            <source>the curve of P₀…P%1</source>
            <translation>la corba de P₀…P%1</translation>
        </message>
        <message>
            <source>the point P₀ alone</source>
            <translation>el punt P₀ tot sol</translation>
        </message>
        <message>
            <source>level %1: the points %2(t)</source>
            <translation>nivell %1: els punts %2(t)</translation>
        </message>
        <message>
            <source>Samples: %1</source>
            <translation>Mostres: %1</translation>
        </message>
        <message>
            <source>Play t</source>
            <translation>Reprodueix t</translation>
        </message>
        <message>
            <source>Move t</source>
            <translation>Mou t</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="502" />
            <source>Pause</source>
            <translation>Pausa</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="502" />
            <source>Play</source>
            <translation>Reprodueix</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="518" />
            <source>At most %1 control points: the degree cannot be raised further.</source>
            <translation>Com a màxim %1 punts de control: el grau no es pot elevar més.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="524" />
            <source>Raise degree to %1</source>
            <translation>Eleva el grau a %1</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="525" />
            <source>Degree raised to %1: the same curve with one control point more.</source>
            <translation>Grau elevat a %1: la mateixa corba amb un punt de control més.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="533" />
            <source>Degree %1 is high: in powers of t the condition number is %2, so only De Casteljau's algorithm, which stays stable, is used here and the exact tables are hidden.</source>
            <translation>El grau %1 és alt: en potències de t el nombre de condició és %2, de manera que aquí només s'usa l'algorisme de De Casteljau, que es manté estable, i s'amaguen les taules exactes.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="552" />
            <source>The exact polynomials need control points that are small fractions: type them in the table (1/3 is accepted) or turn on Snap to grid.</source>
            <translation>Els polinomis exactes necessiten punts de control que siguin fraccions petites: escriviu-los a la taula (s'accepta 1/3) o activeu Ajusta a la quadrícula.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="557" />
            <source>The levels in powers of t are shown up to degree %1; at degree %2 their coefficients would no longer be readable.</source>
            <translation>Els nivells en potències de t es mostren fins al grau %1; amb grau %2 els seus coeficients ja no serien llegibles.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="568" />
            <source>The levels %1 in powers of t (Def 2.4)</source>
            <translation>Els nivells %1 en potències de t (Def 2.4)</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="601" />
            <location filename="../ui/decasteljau_tab.cpp" line="612" />
            <source>De Casteljau's triangle at t = %1 (Def 2.4)</source>
            <translation>Triangle de De Casteljau a t = %1 (Def 2.4)</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="608" />
            <location filename="../ui/decasteljau_tab.cpp" line="622" />
            <source>Split at t: [0, t] has control points %1; [t, 1] has %2.</source>
            <translation>Divisió a t: [0, t] té els punts de control %1; [t, 1] té %2.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="618" />
            <source>The triangle is shown up to degree %1; this curve has degree %2.</source>
            <translation>El triangle es mostra fins al grau %1; aquesta corba té grau %2.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="630" />
            <source>The values are too large for a double (beyond ±1.8e308): a level of the triangle or c′(t) overflows. Move the control points closer to the origin.</source>
            <translation>Els valors són massa grans per a un double (més enllà de ±1,8e308): un nivell del triangle o c′(t) desborda. Acosteu els punts de control a l'origen.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="655" />
            <source>Animate t from 0 to 1 and around again: watch c(t) trace the curve (Def 2.4).</source>
            <translation>Anima t de 0 a 1 i torna a començar: mireu com c(t) traça la corba (Def 2.4).</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="656" />
            <source>Samples:</source>
            <translation>Mostres:</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="658" />
            <source>Sampling precision: the curve is drawn through this many intervals of t, like part in the thesis's Matlab De_Casteljau(P, part).</source>
            <translation>Precisió del mostreig: la corba es dibuixa amb aquest nombre d'intervals de t, com part a la funció de Matlab De_Casteljau(P, part) de la tesi.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="662" />
            <source>Raise degree</source>
            <translation>Eleva el grau</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="663" />
            <source>Degree elevation: the same curve written with one control point more (Qᵢ = i/(n+1) Pᵢ₋₁ + (1 − i/(n+1)) Pᵢ). Undoable.</source>
            <translation>Elevació del grau: la mateixa corba escrita amb un punt de control més (Qᵢ = i/(n+1) Pᵢ₋₁ + (1 − i/(n+1)) Pᵢ). Es pot desfer.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="665" />
            <source>Construction</source>
            <translation>Construcció</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="666" />
            <source>Draw every level Pᵢʳ(t) of De Casteljau's algorithm (Def 2.4): the points of each level and the segments between them, one colour per level.</source>
            <translation>Dibuixa cada nivell Pᵢʳ(t) de l'algorisme de De Casteljau (Def 2.4): els punts de cada nivell i els segments que els uneixen, un color per nivell.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="668" />
            <source>Step by step</source>
            <translation>Pas a pas</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="669" />
            <source>Overlay the curves of the first 1, 2, …, n+1 control points, like the desglossar option of the thesis's Matlab Rep_Bezier.</source>
            <translation>Superposa les corbes dels primers 1, 2, …, n+1 punts de control, com l'opció desglossar de la funció de Matlab Rep_Bezier de la tesi.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="671" />
            <source>Tangent</source>
            <translation>Tangent</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="672" />
            <source>The tangent vector c′(t) = n (P₁ⁿ⁻¹(t) − P₀ⁿ⁻¹(t)), read off the last level but one of the construction; the arrow at c(t) is c′(t)/n, that last segment.</source>
            <translation>El vector tangent c′(t) = n (P₁ⁿ⁻¹(t) − P₀ⁿ⁻¹(t)), llegit al penúltim nivell de la construcció; la fletxa a c(t) és c′(t)/n, aquest últim segment.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="674" />
            <source>Split at t</source>
            <translation>Divideix a t</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="675" />
            <source>Split the curve at t: the two edges of De Casteljau's triangle are the control polygons of the halves [0, t] and [t, 1].</source>
            <translation>Divideix la corba a t: les dues vores del triangle de De Casteljau són els polígons de control de les meitats [0, t] i [t, 1].</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="677" />
            <source>Snap to grid</source>
            <translation>Ajusta a la quadrícula</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="678" />
            <source>Round dragged and added points to the grid, so that they stay small fractions and the exact tables appear.</source>
            <translation>Arrodoneix a la quadrícula els punts arrossegats i afegits, perquè continuïn sent fraccions petites i apareguin les taules exactes.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="680" />
            <source>Control points P0…Pn of the Bézier curve (Def 2.4): drag a point, double-click to add one on the nearest edge, Delete removes the selected one, arrows nudge it. Drag the curve itself to mold it, or mold it at t with Alt+arrows; near the curve its closest point and t are shown.</source>
            <translation>Punts de control P0…Pn de la corba de Bézier (Def 2.4): arrossegueu un punt, feu doble clic per afegir-ne un a l'aresta més propera, Supr elimina el seleccionat i les fletxes el desplacen. Arrossegueu la corba mateixa per modelar-la, o modeleu-la a t amb Alt+fletxes; a prop de la corba se'n mostren el punt més proper i el seu t.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="682" />
            <source>De Casteljau's triangle Pᵢʳ(t) at the current t and, for rational points, every level in powers of t, as in Ex 2.2 and Ex 2.3.</source>
            <translation>Triangle de De Casteljau Pᵢʳ(t) al t actual i, per a punts racionals, cada nivell en potències de t, com a l'Ex 2.2 i l'Ex 2.3.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="717" />
            <source>The De Casteljau points are missing or not a list.</source>
            <translation>Falten els punts de De Casteljau o no són una llista.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="720" />
            <source>The De Casteljau tab needs between 1 and %1 control points; the document has %2.</source>
            <translation>La pestanya De Casteljau necessita entre 1 i %1 punts de control; el document en té %2.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="728" />
            <source>Control point %1 is not a pair of finite numbers.</source>
            <translation>El punt de control %1 no és un parell de nombres finits.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="734" />
            <source>The parameter t must be a number between 0 and 1.</source>
            <translation>El paràmetre t ha de ser un nombre entre 0 i 1.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="741" />
            <source>The number of samples must be a whole number from %1 to %2.</source>
            <translation>El nombre de mostres ha de ser un nombre enter de %1 a %2.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="751" />
            <source>A De Casteljau display option is not true or false.</source>
            <translation>Una opció de visualització de De Casteljau no és true ni false.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="786" />
            <source>Load Ex %1</source>
            <translation>Carrega l'Ex %1</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="789" />
            <source>Ex %1: the tables of the thesis are in the panel on the right at t = 1/2.</source>
            <translation>Ex %1: les taules de la tesi són al quadre de la dreta, a t = 1/2.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.cpp" line="847" />
            <source>Drag a point; double-click to add one; Delete removes the selected point; move t with the slider.</source>
            <translation>Arrossegueu un punt; feu doble clic per afegir-ne un; Supr elimina el punt seleccionat; moveu t amb el control lliscant.</translation>
        </message>
        <message>
            <location filename="../ui/decasteljau_tab.h" line="39" />
            <source>De Casteljau</source>
            <translation>De Casteljau</translation>
        </message>
        <message>
            <source>Control points</source>
            <translation>Punts de control</translation>
        </message>
        <message>
            <source>Draw the control points Pᵢ, their labels and the control polygon; off, the curve alone, like puntsvis = false in the thesis&apos;s Matlab. The table still edits the points.</source>
            <translation>Dibuixa els punts de control Pᵢ, les seves etiquetes i el polígon de control; desactivat, només la corba, com puntsvis = false al Matlab de la tesi. La taula continua editant els punts.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::Document</name>
        <message>
            <source>Tab “%1”: its part of the document is not an object.</source>
            <translation>Pestanya «%1»: la seva part del document no és un objecte.</translation>
        </message>
        <message>
            <source>This document has no "tabs" object holding the tabs' points and settings.</source>
            <translation>Aquest document no té l'objecte "tabs" amb els punts i la configuració de les pestanyes.</translation>
        </message>
        <message>
            <source>This document's "version" is not a whole number; this Granota reads version %1.</source>
            <translation>La "version" d'aquest document no és un nombre enter; aquest Granota llegeix la versió %1.</translation>
        </message>
        <message>
            <source>This is not a Granota document: it is a JSON list, not an object.</source>
            <translation>Això no és un document del Granota: és una llista JSON, no un objecte.</translation>
        </message>
        <message>
            <location filename="../ui/document.cpp" line="33" />
            <source>This is not a Granota document: %1 (at byte %2).</source>
            <translation>Això no és un document del Granota: %1 (al byte %2).</translation>
        </message>
        <message>
            <location filename="../ui/document.cpp" line="40" />
            <source>This is not a Granota document (no "format": "granota").</source>
            <translation>Això no és un document del Granota (no hi ha "format": "granota").</translation>
        </message>
        <message>
            <location filename="../ui/document.cpp" line="45" />
            <source>This document has version %1; this Granota reads version %2.</source>
            <translation>Aquest document és de la versió %1; aquest Granota llegeix la versió %2.</translation>
        </message>
        <message>
            <location filename="../ui/document.cpp" line="61" />
            <source>Tab “%1”: %2</source>
            <translation>Pestanya «%1»: %2</translation>
        </message>
        <message>
            <source>This is not a Granota document: the file is empty.</source>
            <translation>Això no és un document del Granota: el fitxer és buit.</translation>
        </message>
        <message>
            <source>This is not a whole Granota document: the file is cut off at byte %1.</source>
            <translation>Això no és un document del Granota sencer: el fitxer s&apos;acaba a mitges al byte %1.</translation>
        </message>
        <message>
            <source>This is not a Granota document: the text is not JSON at byte %1 (line %2).</source>
            <translation>Això no és un document del Granota: el text no és JSON al byte %1 (línia %2).</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::Exporter</name>
        <message>
            <location filename="../ui/exporter.cpp" line="23" />
            <source>Cannot write “%1”.</source>
            <translation>No es pot escriure «%1».</translation>
        </message>
        <message>
            <location filename="../ui/exporter.cpp" line="36" />
            <source>The resolution must be between 24 and 1200 DPI.</source>
            <translation>La resolució ha d'estar entre 24 i 1200 PPP.</translation>
        </message>
        <message>
            <location filename="../ui/exporter.cpp" line="40" />
            <source>The image would be too large: choose a lower resolution.</source>
            <translation>La imatge seria massa gran: trieu una resolució més baixa.</translation>
        </message>
        <message>
            <location filename="../ui/exporter.cpp" line="43" />
            <source>Not enough memory for an image of %1×%2 pixels.</source>
            <translation>No hi ha prou memòria per a una imatge de %1×%2 píxels.</translation>
        </message>
        <message>
            <location filename="../ui/exporter.cpp" line="64" />
            <source>Made with Granota</source>
            <translation>Fet amb el Granota</translation>
        </message>
        <message>
            <source>Cannot write “%1”: %2.</source>
            <translation>No es pot escriure «%1»: %2.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::FitExactView</name>
        <message>
            <source>M has %1 × %2 entries (a row per data point, a column per control point); the first %3 rows and %4 columns are shown.</source>
            <translation>M té %1 × %2 entrades (una fila per punt de dades, una columna per punt de control); se'n mostren les primeres %3 files i %4 columnes.</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="80" />
            <source>Chord lengths dᵢ = dist(Qᵢ₋₁, Qᵢ)</source>
            <translation>Longituds de corda dᵢ = dist(Qᵢ₋₁, Qᵢ)</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="92" />
            <source>The thesis (Ex 2.9) writes d₄ = √85, from (1 − 7)² + (5 + 2)²; but Q₃ has x = 8, so d₄ = √(49 + 49) = 7√2, which is used here.</source>
            <translation>La tesi (Ex 2.9) escriu d₄ = √85, a partir de (1 − 7)² + (5 + 2)²; però Q₃ té x = 8, per tant d₄ = √(49 + 49) = 7√2, que és el que s'usa aquí.</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="95" />
            <source>Centripetal parameters (beyond the thesis) use √dᵢ instead of dᵢ.</source>
            <translation>Els paràmetres centrípets (més enllà de la tesi) usen √dᵢ en lloc de dᵢ.</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="107" />
            <source>Parameter correction moves the tᵢ to where the points project onto the curve: the results are shown in decimals.</source>
            <translation>La correcció dels paràmetres mou els tᵢ allà on els punts es projecten sobre la corba: els resultats es mostren en decimals.</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="110" />
            <source>Exact fractions are shown for up to %1 data points; these %2 are shown in decimals.</source>
            <translation>Les fraccions exactes es mostren fins a %1 punts de dades; aquests %2 es mostren en decimals.</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="114" />
            <source>The data are not small fractions: the results are shown in decimals.</source>
            <translation>Les dades no són fraccions petites: els resultats es mostren en decimals.</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="120" />
            <source>These parameters are irrational (square roots of the distances), so M cannot be written in fractions: the results are shown in decimals, as the thesis does with Matlab in Ex 2.9 and Ex 2.10.</source>
            <translation>Aquests paràmetres són irracionals (arrels quadrades de les distàncies), així que M no es pot escriure en fraccions: els resultats es mostren en decimals, com fa la tesi amb Matlab a l'Ex 2.9 i l'Ex 2.10.</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="124" />
            <source>MᵀM is singular for these parameters (coincident points): the control points shown are the minimum-norm least-squares solution, in decimals.</source>
            <translation>MᵀM és singular per a aquests paràmetres (punts coincidents): els punts de control que es mostren són la solució de mínims quadrats de norma mínima, en decimals.</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="125" />
            <source>The exact fractions of this fit would take too long to compute (their digits grow with the degree and the number of points): the results are shown in decimals.</source>
            <translation>Les fraccions exactes d’aquest ajust trigarien massa a calcular-se (les seves xifres creixen amb el grau i amb el nombre de punts): els resultats es mostren en decimals.</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="129" />
            <location filename="../ui/fit_exact_view.cpp" line="169" />
            <source>Parameters tᵢ</source>
            <translation>Paràmetres tᵢ</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="136" />
            <source>Matrices (Lemma 2.2, Note 2.2)</source>
            <translation>Matrius (Lema 2.2, Nota 2.2)</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="142" />
            <source>Control points P = M⁺Q</source>
            <translation>Punts de control P = M⁺Q</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="150" />
            <location filename="../ui/fit_exact_view.cpp" line="191" />
            <source>Fitted curve α(t) = Σ Bⱼⁿ(t) Pⱼ</source>
            <translation>Corba ajustada α(t) = Σ Bⱼⁿ(t) Pⱼ</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="156" />
            <source>Ex 2.7: the thesis prints α(t) = (−8/7 + 726/35 t − 600/35 t², 46/35 − 130/35 t + 200/35 t²), the same curve with unreduced fractions (600/35 = 120/7, 130/35 = 26/7, 200/35 = 40/7).</source>
            <translation>Ex 2.7: la tesi escriu α(t) = (−8/7 + 726/35 t − 600/35 t², 46/35 − 130/35 t + 200/35 t²), la mateixa corba amb fraccions sense simplificar (600/35 = 120/7, 130/35 = 26/7, 200/35 = 40/7).</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="160" />
            <source>Ex 2.8: the thesis prints −1636/105 as the coefficient of t in x(t). It is 3(P₁ − P₀) = 3(−3371/630 − 11/70) = −347/21 = −1735/105, shown here.</source>
            <translation>Ex 2.8: la tesi escriu −1636/105 com a coeficient de t a x(t). És 3(P₁ − P₀) = 3(−3371/630 − 11/70) = −347/21 = −1735/105, que és el que es mostra aquí.</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="175" />
            <source>Matrix M (Lemma 2.2), in decimals</source>
            <translation>Matriu M (Lema 2.2), en decimals</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="184" />
            <source>Control points P</source>
            <translation>Punts de control P</translation>
        </message>
        <message>
            <location filename="../ui/fit_exact_view.cpp" line="195" />
            <source>α(t) in powers of t is not shown beyond degree %1: its coefficients grow like C(n, k) and cancel each other.</source>
            <translation>No es mostra α(t) en potències de t més enllà del grau %1: els coeficients creixen com C(n, k) i es cancel·len entre ells.</translation>
        </message>
        <message>
            <source>Annex III&apos;s distances dᵢ = |Qᵢ₋₁| (BezParamProp)</source>
            <translation>Distàncies de l&apos;Annex III dᵢ = |Qᵢ₋₁| (BezParamProp)</translation>
        </message>
        <message>
            <source>Annex III&apos;s BezParamProp, as the thesis&apos;s Matlab computes it: dᵢ = |Qᵢ₋₁|, the distance of the point before from the origin, not from its neighbour — Figs 2.7 and 2.8 were drawn with these parameters (docs/thesis-errata.md).</source>
            <translation>El BezParamProp de l&apos;Annex III, tal com el calcula el Matlab de la tesi: dᵢ = |Qᵢ₋₁|, la distància del punt anterior a l&apos;origen, no al seu veí — les Fig. 2.7 i 2.8 es van dibuixar amb aquests paràmetres (docs/thesis-errata.md).</translation>
        </message>
        <message>
            <source>The Penrose conditions of M⁺ (§2.1.3), checked exactly: %1</source>
            <translation>Les condicions de Penrose de M⁺ (§2.1.3), comprovades exactament: %1</translation>
        </message>
        <message>
            <source>Hessian 2MᵀM (Prop 2.2)</source>
            <translation>Hessiana 2MᵀM (Prop. 2.2)</translation>
        </message>
        <message>
            <source>Its eigenvalues 2σᵢ²: %1 — all positive, so the error&apos;s critical point is its minimum.</source>
            <translation>Els seus valors propis 2σᵢ²: %1 — tots positius, i per tant el punt crític de l&apos;error n&apos;és el mínim.</translation>
        </message>
        <message>
            <source>Its eigenvalues 2σᵢ²: %1.</source>
            <translation>Els seus valors propis 2σᵢ²: %1.</translation>
        </message>
        <message>
            <source>Parameters tᵢ in radicals</source>
            <translation>Paràmetres tᵢ amb radicals</translation>
        </message>
        <message>
            <source>in radicals</source>
            <translation>amb radicals</translation>
        </message>
        <message>
            <source>decimal</source>
            <translation>en decimals</translation>
        </message>
        <message>
            <source>the thesis prints</source>
            <translation>la tesi imprimeix</translation>
        </message>
        <message>
            <source>printed − right</source>
            <translation>imprès − correcte</translation>
        </message>
        <message>
            <source>A quotient whose denominator has more than %1 coprime radicands is left as it stands, not rationalised.</source>
            <translation>Un quocient amb més de %1 radicands primers entre si al denominador es deixa tal qual, sense racionalitzar.</translation>
        </message>
        <message>
            <source>Ex 2.9 and Ex 2.10 print tᵢ rationalised from their d₄ = √85: %1. Each is too large by the difference above (docs/thesis-errata.md, “Ex 2.9 and 2.10”).</source>
            <translation>Els Ex 2.9 i Ex 2.10 imprimeixen els tᵢ racionalitzats a partir del seu d₄ = √85: %1. Cadascun és massa gran en la diferència de dalt (docs/thesis-errata.md, «Ex 2.9 and 2.10»).</translation>
        </message>
        <message>
            <source>The thesis (Ex 2.9) writes d₄ = √85, from (1 − 7)² + (5 + 2)²; but Q₃ has x = 8, so d₄ = √(49 + 49) = 7√2, which is used here (docs/thesis-errata.md, “Ex 2.9 and 2.10”).</source>
            <translation>La tesi (Ex 2.9) escriu d₄ = √85, a partir de (1 − 7)² + (5 + 2)²; però Q₃ té x = 8, per tant d₄ = √(49 + 49) = 7√2, que és el que s&apos;usa aquí (docs/thesis-errata.md, «Ex 2.9 and 2.10»).</translation>
        </message>
        <message>
            <source>Annex III&apos;s BezParamProp, as the thesis&apos;s Matlab computes it: dᵢ = |Qᵢ₋₁|, the distance of the point before from the origin, not from its neighbour — Figs 2.7 and 2.8 were drawn with these parameters (docs/thesis-errata.md, “Annex III”).</source>
            <translation>El BezParamProp de l&apos;Annex III, tal com el calcula el Matlab de la tesi: dᵢ = |Qᵢ₋₁|, la distància del punt anterior a l&apos;origen, no al seu veí — les Fig. 2.7 i 2.8 es van dibuixar amb aquests paràmetres (docs/thesis-errata.md, «Annex III»).</translation>
        </message>
        <message>
            <source>Ex 2.7: the thesis prints α(t) = (−8/7 + 726/35 t − 600/35 t², 46/35 − 130/35 t + 200/35 t²), the same curve with unreduced fractions (600/35 = 120/7, 130/35 = 26/7, 200/35 = 40/7); its sum runs k = 0…4 where n = 2 has three control points (docs/thesis-errata.md, “Ex 2.7 and 2.8”).</source>
            <translation>Ex 2.7: la tesi escriu α(t) = (−8/7 + 726/35 t − 600/35 t², 46/35 − 130/35 t + 200/35 t²), la mateixa corba amb fraccions sense simplificar (600/35 = 120/7, 130/35 = 26/7, 200/35 = 40/7); el seu sumatori va de k = 0 a 4 on n = 2 té tres punts de control (docs/thesis-errata.md, «Ex 2.7 and 2.8»).</translation>
        </message>
        <message>
            <source>Ex 2.8: the thesis prints −1636/105 as the coefficient of t in x(t). It is 3(P₁ − P₀) = 3(−3371/630 − 11/70) = −347/21 = −1735/105, shown here (docs/thesis-errata.md, “Ex 2.8”). Its sum also runs k = 0…4, with Bₖ², where n = 3 (“Ex 2.7 and 2.8”).</source>
            <translation>Ex 2.8: la tesi escriu −1636/105 com a coeficient de t a x(t). És 3(P₁ − P₀) = 3(−3371/630 − 11/70) = −347/21 = −1735/105, que és el que es mostra aquí (docs/thesis-errata.md, «Ex 2.8»). El seu sumatori també va de k = 0 a 4, amb Bₖ², on n = 3 («Ex 2.7 and 2.8»).</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::FitTab</name>
        <message numerus="yes">
            <source>%n degree(s) left blank: the fit failed there.
Choose QR or SVD.</source>
            <translation>
                <numerusform>%n grau en blanc: l’ajust hi ha fallat.
Trieu QR o SVD.</numerusform>
                <numerusform>%n graus en blanc: l’ajust hi ha fallat.
Trieu QR o SVD.</numerusform>
            </translation>
        </message>
        <message>
            <source>Comb scale</source>
            <translation>Escala de la pinta</translation>
        </message>
        <message>
            <source>“curvatureCombScale” must be 0 (automatic) or a positive number up to %1.</source>
            <translation>«curvatureCombScale» ha de ser 0 (automàtica) o un nombre positiu fins a %1.</translation>
        </message>
        <message>
            <source>“curvatureComb” must be true or false.</source>
            <translation>«curvatureComb» ha de ser true o false.</translation>
        </message>
        <message>
            <source>The curvature comb of the fitted curve (beyond the thesis): teeth along the normal as long as |κ| times the scale in the key, and the line through their tips; where the comb wiggles, so does the fit.</source>
            <translation>La pinta de curvatura de la corba ajustada (més enllà de la tesi): pues al llarg de la normal tan llargues com |κ| per l'escala de la llegenda, i la línia que passa per les seves puntes; on la pinta oscil·la, també ho fa l'ajust.</translation>
        </message>
        <message>
            <source>Curvature com&amp;b</source>
            <translation>Pinta de cur&amp;vatura</translation>
        </message>
        <message>
            <source>curvature comb of the fit: teeth |κ| × %1</source>
            <translation>pinta de curvatura de l'ajust: pues |κ| × %1</translation>
        </message>
        <message>
            <source>Curvature comb</source>
            <translation>Pinta de curvatura</translation>
        </message>
        <message numerus="yes">
            <source>Least-squares Bézier curve of degree %1 through %n data point(s); squared error %2.</source>
            <translation>
                <numerusform>Corba de Bézier per mínims quadrats de grau %1 per %n punt de dades; error quadràtic %2.</numerusform>
                <numerusform>Corba de Bézier per mínims quadrats de grau %1 per %n punts de dades; error quadràtic %2.</numerusform>
            </translation>
        </message>
        <message>
            <source>Fitting canvas</source>
            <translation>Llenç de l'ajust</translation>
        </message>
        <message>
            <source>Show matrices</source>
            <translation>Mostra les matrius</translation>
        </message>
        <message>
            <source>Plotted up to n = %1 of %2:
refitting every degree for %3 points
on each change would slow the window.</source>
            <translation>Representat fins a n = %1 de %2:
tornar a ajustar cada grau per a %3 punts
a cada canvi alentiria la finestra.</translation>
        </message>
        <message>
            <source>Degree %1 is refused: the highest is %2, beyond which the Bernstein basis is too ill-conditioned for any solver.</source>
            <translation>Es rebutja el grau %1: el màxim és %2, més enllà del qual la base de Bernstein està massa mal condicionada per a qualsevol mètode de resolució.</translation>
        </message>
        <message>
            <source>The fitting tab holds %1 data points; Granota reads at most %2.</source>
            <translation>La pestanya d'ajust té %1 punts de dades; el Granota en llegeix com a màxim %2.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="146" />
            <source>Drag Qᵢ: the curve is refitted as it moves; Delete removes it.</source>
            <translation>Arrossegueu Qᵢ: la corba es torna a ajustar mentre es mou; Supr l'elimina.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="174" />
            <source>Degree %1 needs %2 data points (n + 1 ≤ k + 1); there are %3, so n ≤ %4.</source>
            <translation>El grau %1 necessita %2 punts de dades (n + 1 ≤ k + 1); n'hi ha %3, per tant n ≤ %4.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="291" />
            <source>Degree %1</source>
            <translation>Grau %1</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="298" />
            <source>Parametrization</source>
            <translation>Parametrització</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="305" />
            <source>Solver</source>
            <translation>Mètode</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="312" />
            <location filename="../ui/fit_tab.cpp" line="319" />
            <source>Parameter correction</source>
            <translation>Correcció dels paràmetres</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="380" />
            <source>Least-squares fit (§2.1.3)</source>
            <translation>Ajust per mínims quadrats (§2.1.3)</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="381" />
            <source>&amp;Degree n:</source>
            <translation>&amp;Grau n:</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="382" />
            <source>n: the fitted Bézier curve has n + 1 control points P₀…Pₙ, so n + 1 ≤ k + 1 data points (§2.1.3, Lemma 2.2). Ex 2.7 uses n = 2, Ex 2.8 n = 3.</source>
            <translation>n: la corba de Bézier ajustada té n + 1 punts de control P₀…Pₙ, per tant n + 1 ≤ k + 1 punts de dades (§2.1.3, Lema 2.2). L'Ex 2.7 usa n = 2 i l'Ex 2.8, n = 3.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="384" />
            <source>&amp;Parameters tᵢ:</source>
            <translation>&amp;Paràmetres tᵢ:</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="385" />
            <source>Uniform, i/k (Ex 2.7, 2.8)</source>
            <translation>Uniforme, i/k (Ex 2.7, 2.8)</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="386" />
            <source>Chord length (Ex 2.9, 2.10)</source>
            <translation>Longitud de corda (Ex 2.9, 2.10)</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="387" />
            <source>Centripetal (beyond the thesis)</source>
            <translation>Centrípeta (més enllà de la tesi)</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="389" />
            <source>Where on the curve each Qᵢ should fall (§2.1.3): uniform tᵢ = i/k; proportional to the chord lengths dᵢ = dist(Qᵢ₋₁, Qᵢ); or centripetal, proportional to √dᵢ.</source>
            <translation>On ha de caure cada Qᵢ sobre la corba (§2.1.3): parametrització uniforme tᵢ = i/k; proporcional a les longituds de corda dᵢ = dist(Qᵢ₋₁, Qᵢ); o centrípeta, proporcional a √dᵢ.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="391" />
            <source>&amp;Solver:</source>
            <translation>&amp;Mètode:</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="392" />
            <source>QR (default)</source>
            <translation>QR (per defecte)</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="393" />
            <source>Normal equations (the thesis)</source>
            <translation>Equacions normals (la tesi)</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="394" />
            <source>SVD (singular values)</source>
            <translation>SVD (valors singulars)</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="395" />
            <source>How MP = Q is solved in the least-squares sense. The thesis solves the normal equations MᵀM P = MᵀQ (Prop 2.2), which square the condition number; QR and SVD work on M itself and stay accurate at high degree.</source>
            <translation>Com es resol MP = Q en el sentit dels mínims quadrats. La tesi resol les equacions normals MᵀM P = MᵀQ (Prop 2.2), que eleven al quadrat el nombre de condició; QR i SVD treballen directament amb M i es mantenen precises en grau alt.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="398" />
            <source>&amp;Correct parameters, at most</source>
            <translation>&amp;Corregeix els paràmetres, com a màxim</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="399" />
            <source>Beyond the thesis: project each Qᵢ onto the fitted curve, take the new tᵢ and fit again, while the error Σ‖Qᵢ − α(tᵢ)‖² drops.</source>
            <translation>Més enllà de la tesi: projecta cada Qᵢ sobre la corba ajustada, pren els nous tᵢ i torna a ajustar, mentre l'error Σ‖Qᵢ − α(tᵢ)‖² baixi.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="401" />
            <source> times</source>
            <translation> vegades</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="402" />
            <source>The largest number of parameter corrections (re-projection and refit).</source>
            <translation>El nombre màxim de correccions dels paràmetres (projecció i nou ajust).</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="403" />
            <source>&amp;Import CSV…</source>
            <translation>&amp;Importa CSV…</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="404" />
            <source>Read the data points Qᵢ from a CSV file (one “x,y” per line) or a JSON list [[x,y],…].</source>
            <translation>Llegeix els punts de dades Qᵢ d'un fitxer CSV (un «x,y» per línia) o d'una llista JSON [[x,y],…].</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="405" />
            <source>Show &amp;matrices</source>
            <translation>Mostra les &amp;matrius</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="406" />
            <source>Show M (Lemma 2.2), MᵀM, (MᵀM)⁻¹ and M⁺ = (MᵀM)⁻¹Mᵀ (Note 2.2), in fractions when the data and the parameters are rational, as in Ex 2.7 and Ex 2.8.</source>
            <translation>Mostra M (Lema 2.2), MᵀM, (MᵀM)⁻¹ i M⁺ = (MᵀM)⁻¹Mᵀ (Nota 2.2), en fraccions quan les dades i els paràmetres són racionals, com a l'Ex 2.7 i l'Ex 2.8.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="408" />
            <source>Quality of the fit (Prop 2.2)</source>
            <translation>Qualitat de l'ajust (Prop 2.2)</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="409" />
            <source>The error that the least-squares curve minimises, and how sensitive the solution is to the data.</source>
            <translation>L'error que minimitza la corba de mínims quadrats, i com de sensible és la solució a les dades.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="411" />
            <source>The data points Qᵢ (round, draggable), the fitted Bézier curve α(t), its control points Pⱼ (square) and control polygon, and the residuals Qᵢ − α(tᵢ).</source>
            <translation>Els punts de dades Qᵢ (rodons, es poden arrossegar), la corba de Bézier ajustada α(t), els seus punts de control Pⱼ (quadrats) i el polígon de control, i els residus Qᵢ − α(tᵢ).</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="413" />
            <source>The parameters, the control points P = M⁺Q and the curve α(t) in powers of t, exact when possible (Ex 2.7–2.10).</source>
            <translation>Els paràmetres, els punts de control P = M⁺Q i la corba α(t) en potències de t, exactes quan és possible (Ex 2.7–2.10).</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="415" />
            <source>The least-squares error Σ‖Qᵢ − α(tᵢ)‖² of the best curve of each degree n for the current parameters (without correction); the circle marks the current n. With fixed tᵢ it can only go down as n grows, unless the solver loses accuracy.</source>
            <translation>L'error de mínims quadrats Σ‖Qᵢ − α(tᵢ)‖² de la millor corba de cada grau n per als paràmetres actuals (sense correcció); el cercle marca la n actual. Amb els tᵢ fixos només pot baixar en augmentar n, tret que el mètode perdi precisió.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="418" />
            <source>degree n</source>
            <translation>grau n</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="419" />
            <source>squared error (log)</source>
            <translation>error quadràtic (log)</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="421" />
            <source>Large data sets are fitted and drawn, but not listed.</source>
            <translation>Els conjunts de dades grans s'ajusten i es dibuixen, però no es llisten.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="432" />
            <source>A least-squares fit needs at least 2 data points.</source>
            <translation>Un ajust per mínims quadrats necessita com a mínim 2 punts de dades.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="434" />
            <source>Degree %1 needs at least %2 data points.</source>
            <translation>El grau %1 necessita com a mínim %2 punts de dades.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="437" />
            <source>The normal equations MᵀM P = MᵀQ cannot be solved here: MᵀM is numerically singular (coincident points, or cond₂(MᵀM) = cond₂(M)² beyond 10¹⁶). Choose QR or SVD.</source>
            <translation>Les equacions normals MᵀM P = MᵀQ no es poden resoldre aquí: MᵀM és numèricament singular (punts coincidents, o cond₂(MᵀM) = cond₂(M)² més enllà de 10¹⁶). Trieu QR o SVD.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="439" />
            <source>The least-squares system has no usable solution here.</source>
            <translation>El sistema de mínims quadrats no té aquí cap solució utilitzable.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="441" />
            <source>The fitted curve does not fit in double precision: lower the degree.</source>
            <translation>La corba ajustada no cap en doble precisió: abaixeu el grau.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="444" />
            <source>A data point is not a finite number.</source>
            <translation>Un punt de dades no és un nombre finit.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="495" />
            <source>Degree lowered to %1: n + 1 control points need at least n + 1 data points, and there are %2.</source>
            <translation>Grau rebaixat a %1: n + 1 punts de control necessiten com a mínim n + 1 punts de dades, i n'hi ha %2.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="546" />
            <source>Squared error Σ‖Qᵢ − α(tᵢ)‖²: %1</source>
            <translation>Error quadràtic Σ‖Qᵢ − α(tᵢ)‖²: %1</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="547" />
            <source>RMS error √(Σ/(k+1)): %1</source>
            <translation>Error quadràtic mitjà √(Σ/(k+1)): %1</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="548" />
            <source>Largest error max‖Qᵢ − α(tᵢ)‖: %1</source>
            <translation>Error màxim max‖Qᵢ − α(tᵢ)‖: %1</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="550" />
            <source>Condition number cond₂(M): infinite (M is singular)</source>
            <translation>Nombre de condició cond₂(M): infinit (M és singular)</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="551" />
            <source>Condition number cond₂(M): %1</source>
            <translation>Nombre de condició cond₂(M): %1</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="553" />
            <source>Parameter corrections that lowered the error: %1</source>
            <translation>Correccions dels paràmetres que han reduït l'error: %1</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="556" />
            <source>⚠ Ill-conditioned: cond₂(M) ≈ %1. The control points are very sensitive to the data; lower the degree.</source>
            <translation>⚠ Mal condicionat: cond₂(M) ≈ %1. Els punts de control són molt sensibles a les dades; abaixeu el grau.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="560" />
            <source>⚠ High degree n = %1: the Bernstein basis grows ill-conditioned (cond₂(M) ≈ %2); a lower degree or a spline is usually the better model.</source>
            <translation>⚠ Grau alt n = %1: la base de Bernstein es torna mal condicionada (cond₂(M) ≈ %2); un grau més baix o un spline sol ser un model millor.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="566" />
            <source>⚠ The normal equations square the condition number: cond₂(MᵀM) ≈ %1, so about %2 of the 16 significant digits may be lost. Choose QR.</source>
            <translation>⚠ Les equacions normals eleven al quadrat el nombre de condició: cond₂(MᵀM) ≈ %1, de manera que es poden perdre unes %2 de les 16 xifres significatives. Trieu QR.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="575" />
            <source>⚠ Only %1 distinct parameters tᵢ for %2 control points: M is rank deficient, and the control points shown are the minimum-norm least-squares solution.</source>
            <translation>⚠ Només %1 paràmetres tᵢ diferents per a %2 punts de control: M no té rang màxim, i els punts de control que es mostren són la solució de mínims quadrats de norma mínima.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="580" />
            <source>No fit: %1</source>
            <translation>Sense ajust: %1</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="593" />
            <source>All the data points coincide: the chord lengths are all zero, so uniform parameters are used instead.</source>
            <translation>Tots els punts de dades coincideixen: les longituds de corda són totes zero, així que s'usen paràmetres uniformes.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="595" />
            <source>All the data points coincide: the curve is that point.</source>
            <translation>Tots els punts de dades coincideixen: la corba és aquest punt.</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/fit_tab.cpp" line="597" />
            <source>Q%1 and Q%2 coincide: a zero chord length gives them the same parameter tᵢ (%n such pair(s)).</source>
            <translation>
                <numerusform>Q%1 i Q%2 coincideixen: una longitud de corda zero els dona el mateix paràmetre tᵢ (%n parell(s) així).</numerusform>
                <numerusform>Q%1 i Q%2 coincideixen: una longitud de corda zero els dona el mateix paràmetre tᵢ (%n parell(s) així).</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="603" />
            <source>The data points are collinear: the fitted curve and its control points lie on their line.</source>
            <translation>Els punts de dades són alineats: la corba ajustada i els seus punts de control són sobre la mateixa recta.</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/fit_tab.cpp" line="677" />
            <source>%n data points: too many to list; they are fitted and drawn.</source>
            <translation>
                <numerusform>%n punts de dades: massa per llistar-los; s'ajusten i es dibuixen.</numerusform>
                <numerusform>%n punts de dades: massa per llistar-los; s'ajusten i es dibuixen.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="706" />
            <source>Load Ex %1</source>
            <translation>Carrega l'Ex %1</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="707" />
            <source>Ex %1 data</source>
            <translation>Dades de l'Ex %1</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="709" />
            <source>Ex %1 settings</source>
            <translation>Configuració de l'Ex %1</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="721" />
            <source>Cannot open “%1”: %2</source>
            <translation>No es pot obrir «%1»: %2</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="725" />
            <source>“%1” is larger than %2 MB; Granota reads data files up to that size.</source>
            <translation>«%1» fa més de %2 MB; Granota llegeix fitxers de dades fins a aquesta mida.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="735" />
            <source>“%1” holds no valid data points, nothing was changed: %2</source>
            <translation>«%1» no conté punts de dades vàlids; no s'ha canviat res: %2</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/fit_tab.cpp" line="740" />
            <source>“%1” has %n point(s); a fit needs at least 2, nothing was changed.</source>
            <translation>
                <numerusform>«%1» té %n punt(s); un ajust en necessita com a mínim 2; no s'ha canviat res.</numerusform>
                <numerusform>«%1» té %n punt(s); un ajust en necessita com a mínim 2; no s'ha canviat res.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="747" />
            <source>“%1” has a coordinate too large for a double; nothing was changed.</source>
            <translation>«%1» té una coordenada massa gran per a un double; no s'ha canviat res.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="751" />
            <source>Import %1</source>
            <translation>Importa %1</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/fit_tab.cpp" line="754" />
            <source>Imported %n data points from “%1”.</source>
            <translation>
                <numerusform>S'han importat %n punts de dades de «%1».</numerusform>
                <numerusform>S'han importat %n punts de dades de «%1».</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="760" />
            <location filename="../ui/fit_tab.cpp" line="767" />
            <source>Import data points</source>
            <translation>Importa punts de dades</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="761" />
            <source>Point files (*.csv *.txt *.json);;All files (*)</source>
            <translation>Fitxers de punts (*.csv *.txt *.json);;Tots els fitxers (*)</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="789" />
            <source>The fitting tab's data points are missing or not a list.</source>
            <translation>Falten els punts de dades de la pestanya d'ajust o no són una llista.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="798" />
            <source>Data point Q%1 is not a pair of finite numbers.</source>
            <translation>El punt de dades Q%1 no és un parell de nombres finits.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="804" />
            <source>The fitting tab needs at least 2 data points.</source>
            <translation>La pestanya d'ajust necessita com a mínim 2 punts de dades.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="812" />
            <source>The degree must be a whole number from 0 to %1.</source>
            <translation>El grau ha de ser un nombre enter de 0 a %1.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="821" />
            <source>Unknown parametrization “%1”.</source>
            <translation>Parametrització desconeguda «%1».</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="830" />
            <source>Unknown solver “%1”.</source>
            <translation>Mètode de resolució desconegut «%1».</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="837" />
            <source>“correctParameters” must be true or false.</source>
            <translation>«correctParameters» ha de ser true o false.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="845" />
            <source>The number of parameter corrections must be a whole number from 1 to %1.</source>
            <translation>El nombre de correccions dels paràmetres ha de ser un nombre enter d'1 a %1.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="852" />
            <source>“showMatrices” must be true or false.</source>
            <translation>«showMatrices» ha de ser true o false.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="858" />
            <source>Open fitting data</source>
            <translation>Obre les dades d'ajust</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="859" />
            <source>Open data points</source>
            <translation>Obre els punts de dades</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="861" />
            <source>Open fitting settings</source>
            <translation>Obre la configuració d'ajust</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.cpp" line="960" />
            <source>Drag a data point Qᵢ and the curve is refitted; double-click adds a point, Delete removes it.</source>
            <translation>Arrossegueu un punt de dades Qᵢ i la corba es torna a ajustar; amb doble clic s'afegeix un punt, Supr l'elimina.</translation>
        </message>
        <message>
            <location filename="../ui/fit_tab.h" line="40" />
            <source>Fitting</source>
            <translation>Ajust</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Cancel·la</translation>
        </message>
        <message>
            <source>Stop correcting the parameters: the curve shown is then the best fit found so far.</source>
            <translation>Deixa de corregir els paràmetres: la corba que es mostra és llavors el millor ajust trobat fins ara.</translation>
        </message>
        <message>
            <source>Cancelling: the fit stops after the correction under way…</source>
            <translation>S&apos;està cancel·lant: l&apos;ajust s&apos;atura després de la correcció en curs…</translation>
        </message>
        <message>
            <source>Fitting in the background: %1 of at most %2 parameter corrections made…</source>
            <translation>S&apos;està ajustant en segon pla: %1 de com a molt %2 correccions dels paràmetres fetes…</translation>
        </message>
        <message>
            <source>Fitting in the background…</source>
            <translation>S&apos;està ajustant en segon pla…</translation>
        </message>
        <message>
            <source>Cancelled after %1 of at most %2 parameter corrections: the curve shown is the best fit found until then.</source>
            <translation>Cancel·lat després de %1 de com a molt %2 correccions dels paràmetres: la corba que es mostra és el millor ajust trobat fins llavors.</translation>
        </message>
        <message>
            <source>Fit cancelled: the curve shown is the best fit found so far.</source>
            <translation>Ajust cancel·lat: la corba que es mostra és el millor ajust trobat fins ara.</translation>
        </message>
        <message>
            <source>Annex III (BezParamProp)</source>
            <translation>Annex III (BezParamProp de la tesi)</translation>
        </message>
        <message>
            <source>Where on the curve each Qᵢ should fall (§2.1.3): uniform tᵢ = i/k; proportional to the chord lengths dᵢ = dist(Qᵢ₋₁, Qᵢ); centripetal, proportional to √dᵢ; or as Annex III&apos;s BezParamProp computes them, with |Qᵢ₋₁| in place of dᵢ (how Figs 2.7 and 2.8 were drawn).</source>
            <translation>On ha de caure cada Qᵢ sobre la corba (§2.1.3): parametrització uniforme tᵢ = i/k; proporcional a les longituds de corda dᵢ = dist(Qᵢ₋₁, Qᵢ); centrípeta, proporcional a √dᵢ; o com la calcula el BezParamProp de l&apos;Annex III, amb |Qᵢ₋₁| en lloc de dᵢ (com es van dibuixar les Fig. 2.7 i 2.8).</translation>
        </message>
        <message>
            <source>Control points</source>
            <translation>Punts de control</translation>
        </message>
        <message>
            <source>Residuals</source>
            <translation>Residus</translation>
        </message>
        <message>
            <source>Step by step</source>
            <translation>Pas a pas</translation>
        </message>
        <message>
            <source>Every parametrization in the plot</source>
            <translation>Cada parametrització al gràfic</translation>
        </message>
        <message>
            <source>Samples: %1</source>
            <translation>Mostres: %1</translation>
        </message>
        <message>
            <source>Drawing</source>
            <translation>Dibuix</translation>
        </message>
        <message>
            <source>Con&amp;trol points</source>
            <translation>Pun&amp;ts de control</translation>
        </message>
        <message>
            <source>Draw the fitted control points Pⱼ (squares), their labels and the control polygon. The thesis&apos;s Figs 2.5–2.8 show the curve and the data alone.</source>
            <translation>Dibuixa els punts de control ajustats Pⱼ (quadrats), les seves etiquetes i el polígon de control. Les Fig. 2.5–2.8 de la tesi mostren només la corba i les dades.</translation>
        </message>
        <message>
            <source>&amp;Residuals</source>
            <translation>&amp;Residus</translation>
        </message>
        <message>
            <source>Draw the segments from α(tᵢ) to each data point Qᵢ: the errors the fit minimises.</source>
            <translation>Dibuixa els segments d&apos;α(tᵢ) a cada punt de dades Qᵢ: els errors que l&apos;ajust minimitza.</translation>
        </message>
        <message>
            <source>Step by st&amp;ep</source>
            <translation>Pas a pa&amp;s</translation>
        </message>
        <message>
            <source>Also draw the Bézier curves of the first 1, 2, …, n+1 fitted control points, thinner and lighter, like the desglossar option of the thesis&apos;s Matlab Rep_BezParamEqui and Rep_BezParamProp (Annex III).</source>
            <translation>Dibuixa també les corbes de Bézier dels primers 1, 2, …, n+1 punts de control ajustats, més primes i clares, com l&apos;opció desglossar del Matlab de la tesi, Rep_BezParamEqui i Rep_BezParamProp (Annex III).</translation>
        </message>
        <message>
            <source>Samp&amp;les:</source>
            <translation>M&amp;ostres:</translation>
        </message>
        <message>
            <source>Sampling precision: the fitted curve is drawn through this many intervals of t, like part in the thesis&apos;s Matlab Rep_BezParamEqui(Q, n, part, desglossar).</source>
            <translation>Precisió del mostreig: la corba ajustada es dibuixa amb aquest nombre d&apos;intervals de t, com part al Matlab de la tesi, Rep_BezParamEqui(Q, n, part, desglossar).</translation>
        </message>
        <message>
            <source>Every parametri&amp;zation in the error plot</source>
            <translation>Cada parametrització al gràfic d&apos;&amp;error</translation>
        </message>
        <message>
            <source>Plot the error against the degree for uniform, chord-length, centripetal and Annex III parameters at once, one line each, to see where each wins.</source>
            <translation>Representa l&apos;error segons el grau per als paràmetres uniformes, de corda, centrípets i de l&apos;Annex III alhora, una línia cadascun, per veure on guanya cadascun.</translation>
        </message>
        <message>
            <source>uniform</source>
            <translation>uniforme</translation>
        </message>
        <message>
            <source>chord length</source>
            <translation>longitud de corda</translation>
        </message>
        <message>
            <source>centripetal</source>
            <translation>centrípeta</translation>
        </message>
        <message>
            <source>Annex III</source>
            <translation>annex III</translation>
        </message>
        <message>
            <source>“samples” must be a whole number from %1 to %2.</source>
            <translation>«samples» ha de ser un nombre enter de %1 a %2.</translation>
        </message>
        <message>
            <source>“%1” must be true or false.</source>
            <translation>«%1» ha de ser cert o fals.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::FrogCanvas</name>
        <message numerus="yes">
            <source>Broad phase: %n candidate pairs, %1 contacts</source>
            <translation>
                <numerusform>Fase ampla: %n parell candidat, %1 contactes</numerusform>
                <numerusform>Fase ampla: %n parells candidats, %1 contactes</numerusform>
            </translation>
        </message>
        <message>
            <source>Broad phase: none, the seed has no collisions (§5.2 is future work)</source>
            <translation>Fase ampla: cap, la llavor no té col·lisions (el §5.2 és treball futur)</translation>
        </message>
        <message>
            <source>Shift+click on a vertex or a joint to follow it with the trail.</source>
            <translation>Maj+clic sobre un vèrtex o una articulació per seguir-lo amb la traça.</translation>
        </message>
        <message>
            <source>Trail of vertex %1 of body %2 (Shift+click a point to follow another)</source>
            <translation>Traça del vèrtex %1 del cos %2 (Maj+clic sobre un punt per seguir-ne un altre)</translation>
        </message>
        <message>
            <source>Trail of joint %1 of chain %2 (Shift+click a point to follow another)</source>
            <translation>Traça de l'articulació %1 de la cadena %2 (Maj+clic sobre un punt per seguir-ne un altre)</translation>
        </message>
        <message>
            <source>The ghost starts with the next Reset: the run so far is too long to replay for it.</source>
            <translation>El fantasma començarà amb el proper reinici: l'execució fins ara és massa llarga per reproduir-la.</translation>
        </message>
        <message>
            <source>The other solver cannot run this scene: %1</source>
            <translation>L'altre mètode no pot executar aquesta escena: %1</translation>
        </message>
        <message>
            <source>Dashed ghost: the stable solver fed the same mouse</source>
            <translation>Fantasma discontinu: el mètode estable amb el mateix ratolí</translation>
        </message>
        <message>
            <source>Dashed ghost: the seed solver fed the same mouse</source>
            <translation>Fantasma discontinu: el mètode llavor amb el mateix ratolí</translation>
        </message>
        <message>
            <source>Dashed ghost: the stable solver fed the same mouse, area error %1 %</source>
            <translation>Fantasma discontinu: el mètode estable amb el mateix ratolí, error d'àrea %1 %</translation>
        </message>
        <message>
            <source>Dashed ghost: the seed solver fed the same mouse, area error %1 %</source>
            <translation>Fantasma discontinu: el mètode llavor amb el mateix ratolí, error d'àrea %1 %</translation>
        </message>
        <message>
            <source>Playing the recorded run back: move the cursor inside a body to take over from step %1.</source>
            <translation>Es reprodueix l'execució enregistrada: moveu el cursor dins d'un cos per prendre'n el relleu des del pas %1.</translation>
        </message>
        <message>
            <source>Playing the recorded run back: press inside a body to take over from step %1.</source>
            <translation>Es reprodueix l'execució enregistrada: premeu dins d'un cos per prendre'n el relleu des del pas %1.</translation>
        </message>
        <message>
            <source>Replaying the recorded run, step %1 of %2: a press on a body takes over from there</source>
            <translation>Es reprodueix l'execució enregistrada, pas %1 de %2: una pulsació sobre un cos en pren el relleu des d'aquí</translation>
        </message>
        <message numerus="yes">
            <source>Fast, %1× real time: %n steps a frame</source>
            <translation>
                <numerusform>Ràpid, %1× el temps real: %n pas per fotograma</numerusform>
                <numerusform>Ràpid, %1× el temps real: %n passos per fotograma</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Slow motion, %1× real time: one step every %n frames, the step itself unchanged</source>
            <translation>
                <numerusform>Càmera lenta, %1× el temps real: un pas cada %n fotogrames, amb el mateix pas</numerusform>
                <numerusform>Càmera lenta, %1× el temps real: un pas cada %n fotogrames, amb el mateix pas</numerusform>
            </translation>
        </message>
        <message>
            <source>%1; area error %2 %.</source>
            <translation>%1; error d'àrea %2 %.</translation>
        </message>
        <message>
            <source>Nothing to grab here: move the cursor inside the body with the arrows.</source>
            <translation>Aquí no hi ha res per agafar: porteu el cursor dins del cos amb les fletxes.</translation>
        </message>
        <message>
            <source>Top of the frame: the scene's upper wall (y = 0)</source>
            <translation>Dalt del marc: la paret superior de l'escena (y = 0)</translation>
        </message>
        <message>
            <source>The body has blown up (area error %1 %): press Reset (R), or switch to the Stable solver</source>
            <translation>El cos ha explotat (error d'àrea %1 %): premeu Reinicia (R) o canvieu al mètode Estable</translation>
        </message>
        <message>
            <source>Area error, mean of the %1 bodies, %2 % · largest stretch %3 %</source>
            <translation>Error d'àrea, mitjana dels %1 cossos, %2 % · estirament màxim %3 %</translation>
        </message>
        <message>
            <source>Body 1 of %1: area %2 px² · target %3 px²</source>
            <translation>Cos 1 de %1: àrea %2 px² · desitjada %3 px²</translation>
        </message>
        <message>
            <source>Body 1 of %1: area %2 px² · target %3 px² (%4 %)</source>
            <translation>Cos 1 de %1: àrea %2 px² · desitjada %3 px² (%4 %)</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/frog_canvas.cpp" line="232" />
            <source>Running %n× slower than real time: a step of this scene is more work than a frame holds</source>
            <translation>
                <numerusform>Va %n× més lent que el temps real: un pas d’aquesta escena és més feina de la que cap en un fotograma</numerusform>
                <numerusform>Va %n× més lent que el temps real: un pas d’aquesta escena és més feina de la que cap en un fotograma</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/frog_canvas.cpp" line="227" />
            <source>Least-squares Bézier fit, degree %1 through %2 points: %3 µs per frame</source>
            <translation>Ajust de Bézier per mínims quadrats, grau %1 per %2 punts: %3 µs per fotograma</translation>
        </message>
        <message>
            <location filename="../ui/frog_canvas.cpp" line="232" />
            <source>Precomputed Bézier points (§4.9): computed once, nothing per frame</source>
            <translation>Punts de Bézier precalculats (§4.9): calculats una sola vegada, res per fotograma</translation>
        </message>
        <message>
            <location filename="../ui/frog_canvas.cpp" line="237" />
            <source>Area %1 px² · target %2 px² (%3 %)</source>
            <translation>Àrea %1 px² · desitjada %2 px² (%3 %)</translation>
        </message>
        <message>
            <location filename="../ui/frog_canvas.cpp" line="240" />
            <source>Area %1 px² · target %2 px²</source>
            <translation>Àrea %1 px² · desitjada %2 px²</translation>
        </message>
        <message>
            <location filename="../ui/frog_canvas.cpp" line="244" />
            <source>Area error %1 % · largest stretch %2 %</source>
            <translation>Error d'àrea %1 % · estirament màxim %2 %</translation>
        </message>
        <message>
            <location filename="../ui/frog_canvas.cpp" line="246" />
            <source>Largest correction %1 · kinetic energy %2 · potential energy %3</source>
            <translation>Correcció màxima %1 · energia cinètica %2 · energia potencial %3</translation>
        </message>
        <message>
            <location filename="../ui/frog_canvas.cpp" line="250" />
            <source>Velocities: this scene has no soft body</source>
            <translation>Velocitats: aquesta escena no té cap cos tou</translation>
        </message>
        <message>
            <location filename="../ui/frog_canvas.cpp" line="253" />
            <source>Frame %1 ms (%2 frames per second) · step %3 ms · drawing %4 ms</source>
            <translation>Fotograma %1 ms (%2 fotogrames per segon) · pas %3 ms · dibuix %4 ms</translation>
        </message>
        <message>
            <location filename="../ui/frog_canvas.cpp" line="257" />
            <source>Paused · step %1 ms · drawing %2 ms</source>
            <translation>En pausa · pas %1 ms · dibuix %2 ms</translation>
        </message>
        <message>
            <location filename="../ui/frog_canvas.cpp" line="258" />
            <source>Step %1</source>
            <translation>Pas %1</translation>
        </message>
        <message>
            <location filename="../ui/frog_canvas.cpp" line="670" />
            <source>Press inside the body to grab it.</source>
            <translation>Premeu dins del cos per agafar-lo.</translation>
        </message>
        <message>
            <source>Ruler: %1. Esc or a right click clears it.</source>
            <translation>Regle: %1. Esc o un clic amb el botó dret l'esborra.</translation>
        </message>
        <message>
            <source>%1 px (Δx %2, Δy %3)</source>
            <translation>%1 px (Δx %2, Δy %3)</translation>
        </message>
        <message>
            <source>Protractor: no joint of this scene has angle limits</source>
            <translation>Transportador: cap articulació d'aquesta escena no té límits d'angle</translation>
        </message>
        <message numerus="yes">
            <source>Protractor: %n of %1 joints held at a limit (red)</source>
            <translation>
                <numerusform>Transportador: %n de %1 articulacions aturades en un límit (en vermell)</numerusform>
                <numerusform>Transportador: %n de %1 articulacions aturades en un límit (en vermell)</numerusform>
            </translation>
        </message>
        <message>
            <source>Ruler: move the cursor with the arrows to the other end, then L.</source>
            <translation>Regle: porteu el cursor amb les fletxes a l'altre extrem i premeu L.</translation>
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
            <translation>px/pas²</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="271" />
            <source>px/step</source>
            <translation>px/pas</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="273" />
            <source>px²</source>
            <translation>px²</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="281" />
            <source>Sides N</source>
            <translation>Costats N</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="282" />
            <source>Radius r</source>
            <translation>Radi r</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="283" />
            <source>Centre (x, y)</source>
            <translation>Centre (x, y)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="284" />
            <source>Frame width</source>
            <translation>Amplada del marc</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="285" />
            <source>Frame height</source>
            <translation>Altura del marc</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="286" />
            <source>Gravity g (x, y)</source>
            <translation>Gravetat g (x, y)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="287" />
            <source>Initial velocity v₀ (x, y)</source>
            <translation>Velocitat inicial v₀ (x, y)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="288" />
            <source>Friction f (x, y)</source>
            <translation>Fregament f (x, y)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="289" />
            <source>Largest move velmax</source>
            <translation>Moviment màxim velmax</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="290" />
            <source>Spring length</source>
            <translation>Longitud dels molls</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="291" />
            <source>Target area</source>
            <translation>Àrea desitjada</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="292" />
            <source>Area factor C</source>
            <translation>Factor d'àrea C</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="293" />
            <source>Grab</source>
            <translation>Agafar</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="294" />
            <source>Bodies</source>
            <translation>Cossos</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="295" />
            <source>Bézier points</source>
            <translation>Punts de Bézier</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="296" />
            <source>Fit degree n</source>
            <translation>Grau de l'ajust n</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="298" />
            <source>Front legs (upper, lower)</source>
            <translation>Potes de davant (superior, inferior)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="298" />
            <source>Back legs (upper, lower)</source>
            <translation>Potes de darrere (superior, inferior)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="299" />
            <source>Link %1</source>
            <translation>Segment %1</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="301" />
            <source>Front right shoulder (min, max)</source>
            <translation>Muscle dret de davant (mín., màx.)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="302" />
            <source>Front left shoulder (min, max)</source>
            <translation>Muscle esquerre de davant (mín., màx.)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="303" />
            <source>Back right shoulder (min, max)</source>
            <translation>Muscle dret de darrere (mín., màx.)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="304" />
            <source>Back left shoulder (min, max)</source>
            <translation>Muscle esquerre de darrere (mín., màx.)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="305" />
            <source>Front elbows (min, max)</source>
            <translation>Colzes de davant (mín., màx.)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="306" />
            <source>Back elbows (min, max)</source>
            <translation>Colzes de darrere (mín., màx.)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="307" />
            <source>Shoulder (min, max)</source>
            <translation>Muscle (mín., màx.)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="308" />
            <source>Elbow (min, max)</source>
            <translation>Colze (mín., màx.)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="316" />
            <source>N (costats): the vertices of the body, a regular polygon built from the top (§4.1). Annex II's frog has N = 10; try 3 to 200. Up to 10000, 100000 vertices in all: beyond about 3000 the stable solver runs slower than real time.</source>
            <translation>N (costats): els vèrtexs del cos, un polígon regular construït des de dalt (§4.1). La granota de l'Annex II en té N = 10; proveu de 3 a 200. Fins a 10000, 100000 vèrtexs en total: per sobre d'uns 3000 el mètode estable va més lent que el temps real.</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="319" />
            <source>r: distance from the centre to each vertex of the starting polygon (§4.1). Annex II takes r = |height/6| from the frame, and so does the scene until a value is set here.</source>
            <translation>r: distància del centre a cada vèrtex del polígon inicial (§4.1). L’annex II pren r = |height/6| del marc, i l’escena també, fins que s’hi posa un valor.</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="321" />
            <source>(c₁, c₂): where the first body starts, in pixels of the frame (y grows downwards). Annex II starts at the frame’s centre, and so does the scene until a value is set here.</source>
            <translation>(c₁, c₂): on comença el primer cos, en píxels del marc (la y creix cap avall). L’annex II comença al centre del marc, i l’escena també, fins que s’hi posa un valor.</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="323" />
            <source>The frame (Processing's size(1280, 720)): vertices stay inside [0, width − 1] × [0, height − 1] (§4.2).</source>
            <translation>El marc (size(1280, 720) de Processing): els vèrtexs es queden dins de [0, amplada − 1] × [0, altura − 1] (§4.2).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="325" />
            <source>g (gravetat): acceleration added to every vertex each step, v(t) = v(t − 1) + g (§4.2).</source>
            <translation>g (gravetat): acceleració que se suma a cada vèrtex a cada pas, v(t) = v(t − 1) + g (§4.2).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="327" />
            <source>v⁰ (velocitat inicial): the velocity the body starts with (§4.2).</source>
            <translation>v⁰ (velocitat inicial): la velocitat amb què comença el cos (§4.2).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="329" />
            <source>f (fregament): share of the velocity kept per step on each axis, f ∈ ]0, 1[ (§4.3).</source>
            <translation>f (fregament): fracció de la velocitat que es conserva a cada pas en cada eix, f ∈ ]0, 1[ (§4.3).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="331" />
            <source>velmax: the largest move of a vertex in one step, per axis (Annex II).</source>
            <translation>velmax: el moviment màxim d'un vèrtex en un pas, per eix (Annex II).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="333" />
            <source>molls: rest length of every edge spring; the springs pull the edges back towards it (§4.4).</source>
            <translation>molls: longitud de repòs de cada moll dels costats; els molls tornen els costats cap a aquesta longitud (§4.4).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="335" />
            <source>Areal: the area the body tries to keep, by the trapezoid rule and edge normals (§4.5). 0 or huge values are allowed.</source>
            <translation>Areal: l'àrea que el cos intenta conservar, amb la regla del trapezi i les normals dels costats (§4.5). Es permeten 0 i valors enormes.</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="338" />
            <source>C (reescala): how strongly each step corrects the area; large values make a stiff body (§4.5).</source>
            <translation>C (reescala): quant corregeix l'àrea cada pas; els valors grans fan un cos rígid (§4.5).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="340" />
            <source>Which vertices hold on to the mouse: all of them (§4.6), those above the grab point (§4.7), or Annex II's fixed anchors {0, 1, N−1, N} (§4.10).</source>
            <translation>Quins vèrtexs queden subjectes al ratolí: tots (§4.6), els que estan per damunt del punt on s'agafa (§4.7) o les àncores fixes {0, 1, N−1, N} de l'Annex II (§4.10).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="343" />
            <source>How many bodies fall and collide (§5.2.2); a broad phase keeps the cost close to linear.</source>
            <translation>Quants cossos cauen i xoquen (§5.2.2); una fase ampla manté el cost gairebé lineal.</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="345" />
            <source>§4.9: the polygon is the control polygon of one Bézier curve, sampled once at this many points by De Casteljau (Def 2.4); the samples become the body's vertices.</source>
            <translation>§4.9: el polígon és el polígon de control d'una corba de Bézier, mostrejada una sola vegada en aquests punts amb De Casteljau (Def 2.4); les mostres esdevenen els vèrtexs del cos.</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="348" />
            <source>§4.9, the abandoned option: the degree n of the least-squares Bézier curve fitted to the outline every frame (Lemma 2.2, Prop 2.2).</source>
            <translation>§4.9, l'opció descartada: el grau n de la corba de Bézier d'ajust per mínims quadrats de la silueta a cada fotograma (Lema 2.2, Prop 2.2).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="351" />
            <source>longit: lengths of the two segments of each leg, shoulder–elbow and elbow–wrist (§4.16, Annex II).</source>
            <translation>longit: longituds dels dos segments de cada pota, muscle–colze i colze–canell (§4.16, Annex II).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="353" />
            <source>Length of this link of the pendulum; the links keep their length exactly (§4.13, §4.14).</source>
            <translation>Longitud d'aquest segment del pèndol; els segments conserven exactament la seua longitud (§4.13, §4.14).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="356" />
            <source>angles: smallest and largest angle between the two segments at the elbow, in degrees (§4.15; Annex II uses ±π/12 in front, ±π/3 behind).</source>
            <translation>angles: angle mínim i màxim entre els dos segments al colze, en graus (§4.15; l'Annex II usa ±π/12 davant i ±π/3 darrere).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="358" />
            <source>anglesc: smallest and largest angle of the upper segment at the shoulder, in degrees (§4.15; Annex II uses 0 to π and −π to 0).</source>
            <translation>anglesc: angle mínim i màxim del segment superior al muscle, en graus (§4.15; l'Annex II usa de 0 a π i de −π a 0).</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="375" />
            <source>All vertices (§4.6)</source>
            <translation>Tots els vèrtexs (§4.6)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="376" />
            <source>Above the mouse (§4.7)</source>
            <translation>Per damunt del ratolí (§4.7)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="377" />
            <source>Anchors {0, 1, N−1, N} (§4.10)</source>
            <translation>Àncores {0, 1, N−1, N} (§4.10)</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="383" />
            <source>The obstacles come from the scene file.</source>
            <translation>Els obstacles vénen del fitxer de l'escena.</translation>
        </message>
        <message>
            <location filename="../ui/frog_parameters_panel.cpp" line="384" />
            <source>The shapes of the bodies come from the scene file.</source>
            <translation>Les formes dels cossos vénen del fitxer de l'escena.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::FrogTab</name>
        <message numerus="yes">
            <source>The scene starts again; Undo brings back the run of %n step(s) it replaced.</source>
            <translation>
                <numerusform>L&apos;escena torna a començar; Desfés recupera l&apos;execució d&apos;%n pas que ha substituït.</numerusform>
                <numerusform>L&apos;escena torna a començar; Desfés recupera l&apos;execució de %n passos que ha substituït.</numerusform>
            </translation>
        </message>
        <message>
            <source>A dashpot along each edge, as a damping ratio: 0 none, 1 critical (an edge stretched and let go comes back without ringing), above 1 slower still. What it takes shows in the plots as damping. The run goes on with it from the next step, and the recording keeps the change.</source>
            <translation>Un amortidor al llarg de cada aresta, com a raó d'esmorteïment: 0 cap, 1 crític (una aresta estirada i deixada anar torna sense vibrar), per sobre d'1 encara més lenta. El que s'emporta surt als gràfics com a esmorteïment. La simulació continua amb el valor nou des del pas següent, i l'enregistrament guarda el canvi.</translation>
        </message>
        <message>
            <source>Edge damping ratio ζ</source>
            <translation>Raó d'esmorteïment de les arestes ζ</translation>
        </message>
        <message>
            <source>The same stiffness as a frequency, as Box2D states its soft constraints: how many times a second an edge of this body rings on its own (α = 0, rigid, rings at none). Setting it sets the compliance.</source>
            <translation>La mateixa rigidesa com a freqüència, com Box2D expressa les seves restriccions toves: quantes vegades per segon vibra tota sola una aresta d'aquest cos (α = 0, rígida, no vibra). En fixar-la es fixa la flexibilitat.</translation>
        </message>
        <message>
            <source> Hz</source>
            <translation> Hz</translation>
        </message>
        <message>
            <source>Edge frequency f</source>
            <translation>Freqüència de les arestes f</translation>
        </message>
        <message>
            <source>§5.2.2: the pairs of bodies whose boxes overlap, the only ones tested for contact (a uniform grid finds them), and how many contacts there are (stable solver).</source>
            <translation>§5.2.2: els parells de cossos les capses dels quals se superposen, els únics en què es comprova el contacte (els troba una graella uniforme), i quants contactes hi ha (mètode estable).</translation>
        </message>
        <message>
            <source>Broad phase</source>
            <translation>Fase ampla</translation>
        </message>
        <message>
            <source>The path of one point over the last 10 s: the pendulum's tip or the first body's vertex 0; Shift+click on a vertex or a joint to follow it.</source>
            <translation>El camí d'un punt durant els darrers 10 s: la punta del pèndol o el vèrtex 0 del primer cos; Maj+clic sobre un vèrtex o una articulació per seguir-lo.</translation>
        </message>
        <message>
            <source>Trail</source>
            <translation>Traça</translation>
        </message>
        <message>
            <source>Stopwatch: marked step %1; M again clears the mark.</source>
            <translation>Cronòmetre: s'ha marcat el pas %1; M de nou esborra la marca.</translation>
        </message>
        <message>
            <source>Marks the step shown; the label then counts the steps and seconds since it, as the run goes on or the timeline moves (M). Again: clears the mark.</source>
            <translation>Marca el pas que es mostra; l'etiqueta compta llavors els passos i els segons des d'aquest, mentre l'execució continua o la línia de temps es mou (M). Un altre cop: esborra la marca.</translation>
        </message>
        <message>
            <source>Stopwatch</source>
            <translation>Cronòmetre</translation>
        </message>
        <message numerus="yes">
            <source>%1 s (%n steps) before step %2</source>
            <translation>
                <numerusform>%1 s (%n pas) abans del pas %2</numerusform>
                <numerusform>%1 s (%n passos) abans del pas %2</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%1 s (%n steps) since step %2</source>
            <translation>
                <numerusform>%1 s (%n pas) des del pas %2</numerusform>
                <numerusform>%1 s (%n passos) des del pas %2</numerusform>
            </translation>
        </message>
        <message>
            <source>Both solvers at once: the other solver runs the same scene, fed the same mouse, and is drawn dashed over this one (the seed's frog sits about 17 % short of its area, the stable one holds it).</source>
            <translation>Els dos mètodes alhora: l'altre mètode executa la mateixa escena, amb el mateix ratolí, i es dibuixa amb traç discontinu sobre aquest (la granota de la llavor queda un 17 % per sota de la seva àrea; l'estable la manté).</translation>
        </message>
        <message>
            <source>Ghost of the other solver</source>
            <translation>Fantasma de l'altre mètode</translation>
        </message>
        <message>
            <source>This scene has no springs: the compliance and the damping ratio do nothing here.</source>
            <translation>Aquesta escena no té molles: aquí la flexibilitat i la raó d'esmorteïment no fan res.</translation>
        </message>
        <message>
            <source>α = 0: the edges are rigid.</source>
            <translation>α = 0: les arestes són rígides.</translation>
        </message>
        <message>
            <source>An edge of %1 px rings with a period of %2 steps (%3 Hz at 60 steps a second); 0 makes the edges rigid.</source>
            <translation>Una aresta de %1 px vibra amb un període de %2 passos (%3 Hz a 60 passos per segon); 0 fa les arestes rígides.</translation>
        </message>
        <message>
            <source>The soft-body report below the tab: XPBD's constraint error against the substeps and their cost (View ▸ Error against run time).</source>
            <translation>L'informe del cos tou sota la pestanya: l'error de les restriccions de l'XPBD segons els subpassos i el seu cost (Visualitza ▸ Error respecte del temps d'execució).</translation>
        </message>
        <message>
            <source>Error against substeps…</source>
            <translation>Error segons els subpassos…</translation>
        </message>
        <message>
            <source>How soft the body's edges are, in step² per unit of mass and per px of rest length: 0 is rigid, larger is softer. Unlike the seed's factors it does not depend on the substeps or the number of vertices. The run goes on with it from the next step, and the recording keeps the change.</source>
            <translation>Com de toves són les arestes del cos, en pas² per unitat de massa i per px de longitud en repòs: 0 és rígid, més gran és més tou. A diferència dels factors de la llavor, no depèn dels subpassos ni del nombre de vèrtexs. La simulació continua amb el valor nou des del pas següent, i l'enregistrament guarda el canvi.</translation>
        </message>
        <message>
            <source>Edge compliance α</source>
            <translation>Flexibilitat de les arestes α</translation>
        </message>
        <message>
            <source>Substeps per step, 1 to 32: each step is cut into n substeps, and the constraints' error falls like 1/n² at a cost proportional to n. The run goes on with it from the next step, and the recording keeps the change.</source>
            <translation>Subpassos per pas, d'1 a 32: cada pas es divideix en n subpassos, i l'error de les restriccions baixa com 1/n² amb un cost proporcional a n. La simulació continua amb el valor nou des del pas següent, i l'enregistrament guarda el canvi.</translation>
        </message>
        <message>
            <source>Substeps n</source>
            <translation>Subpassos n</translation>
        </message>
        <message>
            <source>Stable solver</source>
            <translation>Mètode estable</translation>
        </message>
        <message>
            <source>The same scene and values on the stable solver (XPBD), which holds them.</source>
            <translation>La mateixa escena i els mateixos valors amb el mètode estable (XPBD), que els aguanta.</translation>
        </message>
        <message>
            <source>Use the Stable solver</source>
            <translation>Usa el mètode Estable</translation>
        </message>
        <message>
            <source>The body has blown up.</source>
            <translation>El cos ha explotat.</translation>
        </message>
        <message>
            <source>The run was saved at step %1: drag the timeline to go there (it is long to replay).</source>
            <translation>L'execució es va desar al pas %1: arrossegueu la línia de temps per anar-hi (és llarga de reproduir).</translation>
        </message>
        <message>
            <source>The frog's recording was refused: %1</source>
            <translation>S'ha refusat l'enregistrament de la granota: %1</translation>
        </message>
        <message>
            <source>Step 0: the run starts here.</source>
            <translation>Pas 0: l'execució comença aquí.</translation>
        </message>
        <message>
            <source>Step %1 of %2 · %3 s</source>
            <translation>Pas %1 de %2 · %3 s</translation>
        </message>
        <message>
            <source>Timeline</source>
            <translation>Línia de temps</translation>
        </message>
        <message>
            <source>The run so far, step by step: drag to go back to any step (the run pauses there). Running on replays what was recorded until a press on a body, a spawn or a change takes over (, one step back, . one step on).</source>
            <translation>L'execució fins ara, pas a pas: arrossegueu per tornar a qualsevol pas (l'execució s'hi atura). En continuar, es reprodueix el que s'ha enregistrat fins que una pulsació sobre un cos, un cos nou o un canvi en pren el relleu (, un pas enrere, . un pas endavant).</translation>
        </message>
        <message>
            <source>Under the canvas: the energies, what damping and the rest took, the area error, the largest stretch and the contacts as the run goes on; the pendulums' phase plot. Pause freezes them; they export as CSV.</source>
            <translation>Sota el llenç: les energies, el que s’han endut l’esmorteïment i la resta, l’error d’àrea, l’estirament màxim i els contactes al llarg de l’execució; el diagrama de fases dels pèndols. La pausa els atura; s’exporten en CSV.</translation>
        </message>
        <message>
            <source>Plots over time</source>
            <translation>Gràfics en el temps</translation>
        </message>
        <message>
            <source>The speed must be one of 0.125, 0.25, 0.5, 1, 2 and 4.</source>
            <translation>La velocitat ha de ser 0.125, 0.25, 0.5, 1, 2 o 4.</translation>
        </message>
        <message>
            <source>Slow motion steps once every few frames and fast runs several steps a frame: the step itself never changes, so the seed goes through exactly the states of Annex II ([ slower, ] faster).</source>
            <translation>La càmera lenta fa un pas cada pocs fotogrames i la ràpida en fa diversos per fotograma: el pas mateix no canvia mai, així que la llavor passa exactament pels estats de l’Annex II ([ més lent, ] més ràpid).</translation>
        </message>
        <message>
            <source>Speed</source>
            <translation>Velocitat</translation>
        </message>
        <message>
            <source>Scene %1, %2 solver</source>
            <translation>Escena %1, mètode %2</translation>
        </message>
        <message>
            <source>Frog canvas</source>
            <translation>Llenç de la granota</translation>
        </message>
        <message>
            <source>Drag the body with the mouse; Space on the canvas spawns one at the mouse. P pauses, S steps, R resets.</source>
            <translation>Arrossegueu el cos amb el ratolí; l'espai sobre el llenç en fa aparèixer un on és el ratolí. P atura, S avança un pas, R reinicia.</translation>
        </message>
        <message>
            <source>Solver: %1</source>
            <translation>Mètode: %1</translation>
        </message>
        <message>
            <source>Stage: %1</source>
            <translation>Etapa: %1</translation>
        </message>
        <message>
            <source>The seed solver has no angle constraints: these shapes round into blobs. The Stable solver keeps their form.</source>
            <translation>El mètode de la llavor no té restriccions d'angle: aquestes formes s'arrodoneixen fins a semblar bombolles. El mètode estable en manté la forma.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="229" />
            <location filename="../ui/frog_tab.cpp" line="560" />
            <source>Cost of the fit: %1 µs per frame.</source>
            <translation>Cost de l'ajust: %1 µs per fotograma.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="264" />
            <source>The simulation cannot be built with these values: %1</source>
            <translation>No es pot construir la simulació amb aquests valors: %1</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="280" />
            <source>Unknown scene “%1”. The scenes are: %2.</source>
            <translation>Escena desconeguda «%1». Les escenes són: %2.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="330" />
            <source>The scene starts again.</source>
            <translation>L'escena torna a començar.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="382" />
            <location filename="../ui/frog_tab.cpp" line="641" />
            <source>Scene “%1” has no parameter “%2”.</source>
            <translation>L'escena «%1» no té el paràmetre «%2».</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="391" />
            <location filename="../ui/frog_tab.cpp" line="649" />
            <source>This value was refused: %1</source>
            <translation>S'ha rebutjat aquest valor: %1</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="409" />
            <source>Change %1</source>
            <translation>Canvia %1</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="447" />
            <source>Polygon and mouse</source>
            <translation>Polígon i ratolí</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="448" />
            <source>Gravity</source>
            <translation>Gravetat</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="449" />
            <source>Bounce</source>
            <translation>Rebot</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="450" />
            <source>Springs</source>
            <translation>Molls</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="451" />
            <source>Area</source>
            <translation>Àrea</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="452" />
            <source>Verlet and grabbing</source>
            <translation>Verlet i agafar el cos</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="453" />
            <source>Tuned parameters</source>
            <translation>Ajust de paràmetres</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="454" />
            <source>Colour fill</source>
            <translation>Color</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="455" />
            <source>Bézier outline</source>
            <translation>Silueta de Bézier</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="456" />
            <source>Revised Bézier</source>
            <translation>Revisió de Bézier</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="457" />
            <source>Catmull-Rom outline</source>
            <translation>Silueta de Catmull-Rom</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="458" />
            <source>Pendulum</source>
            <translation>Pèndol</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="459" />
            <source>Chain of joints</source>
            <translation>Cadena d'articulacions</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="460" />
            <source>Angle limits</source>
            <translation>Restriccions angulars</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="461" />
            <source>The frog</source>
            <translation>La granota</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="462" />
            <source>Obstacles</source>
            <translation>Obstacles</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="463" />
            <source>Many bodies</source>
            <translation>Diversos cossos</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="464" />
            <source>Other shapes</source>
            <translation>Altres formes</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="471" />
            <source>A regular polygon drawn with straight lines; its radius follows the mouse, r = |mouseY − h/2|.</source>
            <translation>Un polígon regular dibuixat amb línies rectes; el seu radi segueix el ratolí, r = |mouseY − h/2|.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="473" />
            <source>Every vertex falls with constant acceleration (MRUA) and stops at the edge of the frame.</source>
            <translation>Cada vèrtex cau amb acceleració constant (MRUA) i s'atura a la vora del marc.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="475" />
            <source>At the frame the velocity turns round and keeps a share f of itself; a click starts the polygon again at the mouse.</source>
            <translation>A la vora del marc la velocitat canvia de sentit i en conserva una fracció f; un clic torna a començar el polígon al ratolí.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="478" />
            <source>Springs along the edges pull each pair of neighbours back towards their rest length.</source>
            <translation>Els molls dels costats tornen cada parell de veïns cap a la seua longitud de repòs.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="480" />
            <source>The area, by the trapezoid rule, is pushed back towards the target along the edge normals.</source>
            <translation>L'àrea, per la regla del trapezi, es corregeix cap a l'àrea desitjada al llarg de les normals dels costats.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="482" />
            <source>Verlet integration (Def 3.1). Press inside the body to grab it: every vertex is tied to the mouse.</source>
            <translation>Integració de Verlet (Def 3.1). Premeu dins del cos per agafar-lo: cada vèrtex queda lligat al ratolí.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="484" />
            <source>Only the vertices above the grab point hold on to the mouse.</source>
            <translation>Només els vèrtexs per damunt del punt on s'agafa queden subjectes al ratolí.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="486" />
            <source>The same body, filled with colour.</source>
            <translation>El mateix cos, ple de color.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="488" />
            <source>The polygon's vertices are the control points of one Bézier curve, sampled once. Beside it, the per-frame least-squares fit that the thesis abandoned, with its cost.</source>
            <translation>Els vèrtexs del polígon són els punts de control d'una corba de Bézier, mostrejada una sola vegada. Al costat, l'ajust per mínims quadrats a cada fotograma que la tesi va descartar, amb el seu cost.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="491" />
            <source>Tuned constants, and fixed anchors for grabbing, on the precomputed Bézier points.</source>
            <translation>Constants ajustades i àncores fixes per agafar el cos, sobre els punts de Bézier precalculats.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="493" />
            <source>The outline is a Catmull-Rom curve through the vertices (τ = 1/2, Processing's curveVertex).</source>
            <translation>La silueta és una corba de Catmull-Rom que passa pels vèrtexs (τ = 1/2, el curveVertex de Processing).</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="495" />
            <source>A double pendulum hanging from the mouse; its lengths are restored at once.</source>
            <translation>Un pèndol doble penjat del ratolí; les seues longituds es restableixen immediatament.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="497" />
            <source>A chain of joints following its first joint: each joint is put back at its distance from the previous one.</source>
            <translation>Una cadena d'articulacions que segueix la primera: cada articulació es torna a posar a la seua distància de l'anterior.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="500" />
            <source>A leg: two links with gravity, the frame, and limits on the angles at its joints.</source>
            <translation>Una pota: dos segments amb gravetat, el marc i límits als angles de les articulacions.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="502" />
            <source>Body, four legs and head: the final program of Annex II.</source>
            <translation>Cos, quatre potes i cap: el programa final de l'Annex II.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="504" />
            <source>Fixed segments and polygons that the bodies collide with (future work, §5.2).</source>
            <translation>Segments i polígons fixos amb què xoquen els cossos (treball futur, §5.2).</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="506" />
            <source>Several bodies collide with each other; a broad phase keeps the cost close to linear.</source>
            <translation>Diversos cossos xoquen entre si; una fase ampla manté el cost gairebé lineal.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="508" />
            <source>Bodies that are not regular polygons, kept in shape by angle constraints between their edges.</source>
            <translation>Cossos que no són polígons regulars, que mantenen la forma amb restriccions d'angle entre els costats.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="515" />
            <source>The pendulum hangs from the mouse: move the mouse over the picture.</source>
            <translation>El pèndol penja del ratolí: moveu el ratolí per damunt de la imatge.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="518" />
            <source>Move the mouse up and down: the radius is r = |mouseY − h/2| (§4.1).</source>
            <translation>Moveu el ratolí amunt i avall: el radi és r = |mouseY − h/2| (§4.1).</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="520" />
            <source>Click to start the polygon again at the mouse (§4.3).</source>
            <translation>Feu clic per tornar a començar el polígon al ratolí (§4.3).</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="521" />
            <source>Reset (R) drops the polygon again.</source>
            <translation>Reinicia (R) torna a deixar caure el polígon.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="523" />
            <source>Drag the body with the left button. Space drops a new one at the mouse and holds it until you let go (Annex II).</source>
            <translation>Arrossegueu el cos amb el botó esquerre. L'espai en crea un de nou al ratolí i el manté agafat fins que el deixeu anar (Annex II).</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="529" />
            <source>Scene</source>
            <translation>Escena</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="530" />
            <source>Stage</source>
            <translation>Etapa</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="533" />
            <source>The stages of chapter 4, in the thesis's order, and the future work of §5.2. Each scene builds, draws and shows only its own components.</source>
            <translation>Les etapes del capítol 4, en l'ordre de la tesi, i les propostes de treball futur del §5.2. Cada escena construeix, dibuixa i mostra només els seus components.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="536" />
            <source>Solver</source>
            <translation>Mètode</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="537" />
            <source>Seed (Annex II)</source>
            <translation>Llavor (Annex II)</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="538" />
            <source>Stable (XPBD)</source>
            <translation>Estable (XPBD)</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="539" />
            <source>Seed: the thesis's own schemes, reproduced faithfully (Annex II). Stable: beyond the thesis, position-based constraints with compliance (XPBD) that hold the target area and stay stable on stiff and extreme settings. Switching starts the scene again.</source>
            <translation>Llavor: els esquemes de la mateixa tesi, reproduïts fidelment (Annex II). Estable: més enllà de la tesi, restriccions sobre les posicions amb flexibilitat (XPBD) que mantenen l'àrea desitjada i són estables amb valors rígids i extrems. En canviar, l'escena torna a començar.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="542" />
            <source>Run</source>
            <translation>Continua</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="542" />
            <source>Pause</source>
            <translation>Pausa</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="543" />
            <source>Pause or run the animation, one fixed step per frame at 60 frames per second (P).</source>
            <translation>Atura o continua l'animació, un pas fix per fotograma a 60 fotogrames per segon (P).</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="544" />
            <source>Step</source>
            <translation>Pas</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="545" />
            <source>One fixed step, as one call of actualitza() in Annex II; pauses first (S or .).</source>
            <translation>Un pas fix, com una crida a actualitza() de l'Annex II; primer atura l'animació (S o .).</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="546" />
            <source>Reset</source>
            <translation>Reinicia</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="547" />
            <source>Start the scene again with the current parameters (R).</source>
            <translation>Torna a començar l'escena amb els paràmetres actuals (R).</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="549" />
            <source>Bézier outline (§4.9)</source>
            <translation>Silueta de Bézier (§4.9)</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="550" />
            <source>Precomputed points</source>
            <translation>Punts precalculats</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="551" />
            <source>The thesis's choice (§4.9, §4.10): the polygon is the control polygon of a Bézier curve sampled once by De Casteljau (Def 2.4); the samples are the body's vertices.</source>
            <translation>L'opció de la tesi (§4.9, §4.10): el polígon és el polígon de control d'una corba de Bézier mostrejada una sola vegada amb De Casteljau (Def 2.4); les mostres són els vèrtexs del cos.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="553" />
            <source>Least-squares fit every frame</source>
            <translation>Ajust per mínims quadrats a cada fotograma</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="554" />
            <source>The option §4.9 abandoned as too costly for Processing: every frame, the least-squares Bézier curve through the outline (Lemma 2.2, Prop 2.2). With M⁺ computed once, a frame costs one small matrix product; the curve need not pass through the vertices (Note 2.3).</source>
            <translation>L'opció que §4.9 va descartar per massa costosa per a Processing: a cada fotograma, la corba de Bézier d'ajust per mínims quadrats de la silueta (Lema 2.2, Prop 2.2). Amb M⁺ calculada una sola vegada, cada fotograma costa un petit producte de matrius; la corba no té per què passar pels vèrtexs (Nota 2.3).</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="558" />
            <source>Precomputed points: nothing to compute per frame.</source>
            <translation>Punts precalculats: res a calcular a cada fotograma.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="562" />
            <source>Parameters</source>
            <translation>Paràmetres</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="563" />
            <source>Only this scene's parameters, with the names of Annex II. Changes apply at once: the scene starts again with them.</source>
            <translation>Només els paràmetres d'aquesta escena, amb els noms de l'Annex II. Els canvis s'apliquen immediatament: l'escena torna a començar amb ells.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="567" />
            <source>Overlays</source>
            <translation>Capes</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="568" />
            <source>Vertices</source>
            <translation>Vèrtexs</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="569" />
            <source>The body's vertices, numbered as in Annex II's arrays (v₀ under the head), and the joints of the legs.</source>
            <translation>Els vèrtexs del cos, numerats com als vectors de l'Annex II (v₀ sota el cap), i les articulacions de les potes.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="572" />
            <source>The polygon's edges: the springs of §4.4 that keep neighbours at their length.</source>
            <translation>Els costats del polígon: els molls de §4.4 que mantenen els veïns a la seua distància.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="573" />
            <source>Area vs target</source>
            <translation>Àrea i àrea desitjada</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="574" />
            <source>The body's area by the trapezoid rule against the target area (§4.5); the bar's mark is the target.</source>
            <translation>L'àrea del cos per la regla del trapezi comparada amb l'àrea desitjada (§4.5); la marca de la barra és l'àrea desitjada.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="576" />
            <source>Velocities</source>
            <translation>Velocitats</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="577" />
            <source>Each vertex's move in the last step, x − x_prev (Verlet, Def 3.1), drawn four times longer.</source>
            <translation>El desplaçament de cada vèrtex en l'últim pas, x − x_prev (Verlet, Def 3.1), dibuixat quatre vegades més llarg.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="579" />
            <source>Readouts</source>
            <translation>Mesures</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="580" />
            <source>What the solver measures: area error, largest stretch of an edge, largest correction or constraint force, kinetic and potential energy.</source>
            <translation>El que mesura el mètode: error d'àrea, estirament màxim d'un costat, correcció o força de restricció màxima, energia cinètica i potencial.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="582" />
            <source>Frame time</source>
            <translation>Temps per fotograma</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="583" />
            <source>Time per frame and per simulation step, in milliseconds, averaged a few times a second.</source>
            <translation>Temps per fotograma i per pas de simulació, en mil·lisegons, amb la mitjana actualitzada unes quantes vegades per segon.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="617" />
            <source>The scene “%1” cannot be loaded: %2</source>
            <translation>No es pot carregar l’escena «%1»: %2</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="625" />
            <source>Unknown solver “%1” (seed or stable).</source>
            <translation>Mètode desconegut «%1» (seed, el de la llavor, o stable, l’estable).</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="633" />
            <source>The frog's parameters must be an object.</source>
            <translation>Els paràmetres de la granota han de ser un objecte.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="658" />
            <source>The frog's overlays must be an object.</source>
            <translation>Les capes de la granota han de ser un objecte.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="670" />
            <source>The overlay “%1” must be true or false.</source>
            <translation>La capa «%1» ha de ser true o false.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="680" />
            <source>The Bézier outline must be “precomputed” or “fit”, not “%1”.</source>
            <translation>La silueta de Bézier ha de ser «precomputed» o «fit», no «%1».</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="688" />
            <source>“paused” must be true or false.</source>
            <translation>«paused» ha de ser true o false.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="795" />
            <source>The number of frames must be at least 1.</source>
            <translation>El nombre de fotogrames ha de ser com a mínim 1.</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="797" />
            <source>Cannot create the folder “%1”.</source>
            <translation>No es pot crear la carpeta «%1».</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.cpp" line="811" />
            <source>Cannot write “%1”.</source>
            <translation>No es pot escriure «%1».</translation>
        </message>
        <message>
            <location filename="../ui/frog_tab.h" line="33" />
            <source>Frog</source>
            <translation>Granota</translation>
        </message>
        <message>
            <source>The stable solver's knobs were refused: substeps from %1 to %2, compliance from 0 to %3, damping ratio from 0 to %4.</source>
            <translation>S'han refusat els valors del mètode estable: subpassos entre %1 i %2, flexibilitat entre 0 i %3, raó d'esmorteïment entre 0 i %4.</translation>
        </message>
        <message>
            <source>Protractor</source>
            <translation>Transportador</translation>
        </message>
        <message>
            <source>§4.15: each joint's angle, in degrees, over the range its limits allow (shaded); red when the joint is held at a limit.</source>
            <translation>§4.15: l'angle de cada articulació, en graus, sobre l'interval que permeten els seus límits (ombrejat); en vermell quan l'articulació és aturada en un límit.</translation>
        </message>
        <message>
            <source>The ruler must be four numbers: x and y of each end, in px.</source>
            <translation>El regle han de ser quatre nombres: x i y de cada extrem, en px.</translation>
        </message>
        <message>
            <source>The run from before this step was not kept (too much memory): the scene starts again.</source>
            <translation>L&apos;execució d&apos;abans d&apos;aquest pas no s&apos;ha conservat (massa memòria): l&apos;escena torna a començar.</translation>
        </message>
        <message>
            <source>There is no scene to export.</source>
            <translation>No hi ha cap escena per exportar.</translation>
        </message>
        <message>
            <source>Step %1 is no longer recorded.</source>
            <translation>El pas %1 ja no està enregistrat.</translation>
        </message>
        <message>
            <source>Keys: the arrows move the cursor, G grabs, L lays a ruler, Space spawns a body; P pauses, S steps, R resets.</source>
            <translation>Tecles: les fletxes mouen el cursor, G agafa, L posa un regle, l&apos;espai fa aparèixer un cos; P atura, S avança un pas, R reinicia.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::MainWindow</name>
        <message>
            <source>&lt;p&gt;Everything can be done with the keyboard alone: Help ▸ Keyboard shortcuts lists every key.&lt;/p&gt;</source>
            <translation>&lt;p&gt;Tot es pot fer només amb el teclat: Ajuda ▸ Dreceres de teclat llista totes les tecles.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Tabs</source>
            <translation>Pestanyes</translation>
        </message>
        <message>
            <source>Keyboard shortcuts</source>
            <translation>Dreceres de teclat</translation>
        </message>
        <message>
            <source>&amp;Keyboard shortcuts</source>
            <translation>&amp;Dreceres de teclat</translation>
        </message>
        <message>
            <source>Pre&amp;vious tab</source>
            <translation>Pestanya &amp;anterior</translation>
        </message>
        <message>
            <source>&amp;Next tab</source>
            <translation>Pestanya &amp;següent</translation>
        </message>
        <message>
            <source>&amp;Redo %1</source>
            <translation>&amp;Refés %1</translation>
        </message>
        <message>
            <source>&amp;Undo %1</source>
            <translation>&amp;Desfés %1</translation>
        </message>
        <message>
            <source>A Granota session was closed without saving its changes to “%1” (autosaved %2). Recover them?</source>
            <translation>Una sessió del Granota es va tancar sense desar els canvis de «%1» (còpia automàtica del %2). Els voleu recuperar?</translation>
        </message>
        <message>
            <source>A Granota session was closed without saving its Untitled document (autosaved %1). Recover it?</source>
            <translation>Una sessió del Granota es va tancar sense desar el document sense títol (còpia automàtica del %1). El voleu recuperar?</translation>
        </message>
        <message>
            <source>&amp;Discard</source>
            <translation>&amp;Descarta</translation>
        </message>
        <message>
            <source>&amp;Keep for later</source>
            <translation>&amp;Guarda-la per a més tard</translation>
        </message>
        <message>
            <source>&amp;Recover</source>
            <translation>&amp;Recupera</translation>
        </message>
        <message>
            <source>Recovered %1. Not recovered:
%2

The whole autosave is kept as “%3”.</source>
            <translation>S'ha recuperat: %1. No s'ha recuperat:
%2

Tota la còpia automàtica es conserva com a «%3».</translation>
        </message>
        <message>
            <source>Recovered the unsaved work of the last session. The autosave is kept as “%1”.</source>
            <translation>S'ha recuperat la feina sense desar de l'última sessió. La còpia automàtica es conserva com a «%1».</translation>
        </message>
        <message>
            <source>The autosave could not be recovered: %1

It is kept as “%2”.</source>
            <translation>No s'ha pogut recuperar la còpia automàtica: %1

Es conserva com a «%2».</translation>
        </message>
        <message>
            <source>no tab's part could be read.</source>
            <translation>no s'ha pogut llegir la part de cap pestanya.</translation>
        </message>
        <message>
            <source>Granota cannot keep a copy of your unsaved changes: %1

Save the document (Ctrl+S) to keep them. Granota will keep trying.</source>
            <translation>El Granota no pot guardar una còpia dels canvis sense desar: %1

Deseu el document (Ctrl+S) per conservar-los. El Granota ho continuarà intentant.</translation>
        </message>
        <message>
            <source>Autosave failed</source>
            <translation>La còpia automàtica ha fallat</translation>
        </message>
        <message>
            <source>⚠ Not autosaved: save your work</source>
            <translation>⚠ Sense còpia automàtica: deseu la feina</translation>
        </message>
        <message>
            <source>The autosave works again.</source>
            <translation>La còpia automàtica torna a funcionar.</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="156" />
            <source>Loaded Ex %1 of the thesis.</source>
            <translation>S'ha carregat l'Ex %1 de la tesi.</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="248" />
            <source>Ex %1 could not be loaded.</source>
            <translation>No s'ha pogut carregar l'Ex %1.</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="307" />
            <source>&amp;File</source>
            <translation>&amp;Fitxer</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="308" />
            <source>&amp;New</source>
            <translation>&amp;Nou</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="309" />
            <source>&amp;Open…</source>
            <translation>&amp;Obre…</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="310" />
            <source>Open &amp;Recent</source>
            <translation>Obre'n un de &amp;recent</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="311" />
            <source>&amp;Save</source>
            <translation>&amp;Desa</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="312" />
            <source>Save &amp;As…</source>
            <translation>Desa &amp;com a…</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="313" />
            <source>&amp;Export</source>
            <translation>&amp;Exporta</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="314" />
            <source>PNG image…</source>
            <translation>Imatge PNG…</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="315" />
            <source>SVG drawing…</source>
            <translation>Dibuix SVG…</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="316" />
            <source>PDF document…</source>
            <translation>Document PDF…</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="317" />
            <source>CSV data…</source>
            <translation>Dades CSV…</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="318" />
            <source>TikZ picture for LaTeX…</source>
            <translation>Figura TikZ per a LaTeX…</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="319" />
            <source>Frog animation as PNG frames…</source>
            <translation>Animació de la granota en fotogrames PNG…</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="320" />
            <source>&amp;Quit</source>
            <translation>&amp;Surt</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="321" />
            <source>&amp;Edit</source>
            <translation>&amp;Edita</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="322" />
            <source>&amp;Undo</source>
            <translation>&amp;Desfés</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="323" />
            <source>&amp;Redo</source>
            <translation>&amp;Refés</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="324" />
            <source>&amp;View</source>
            <translation>&amp;Visualitza</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="325" />
            <source>&amp;Presentation mode</source>
            <translation>Mode de &amp;presentació</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="326" />
            <source>Full screen, larger text and thicker lines for the classroom.</source>
            <translation>Pantalla completa, text més gran i línies més gruixudes per a l'aula.</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="327" />
            <source>&amp;Error against run time</source>
            <translation>&amp;Error respecte del temps d'execució</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="328" />
            <source>Show, below the tab, how accurate each numerical method is for the time it takes (work-precision plot).</source>
            <translation>Mostra, sota la pestanya, quina precisió dona cada mètode numèric per al temps que triga (gràfic de treball-precisió).</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="330" />
            <source>Zoom &amp;in</source>
            <translation>&amp;Amplia</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="331" />
            <source>Zoom &amp;out</source>
            <translation>&amp;Redueix</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="332" />
            <source>&amp;Fit to view</source>
            <translation>&amp;Encaixa a la vista</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="334" />
            <source>Show %1</source>
            <translation>Mostra %1</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="337" />
            <source>&amp;Language</source>
            <translation>&amp;Llengua</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="338" />
            <source>E&amp;xamples</source>
            <translation>E&amp;xemples</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="340" />
            <source>Ex 2.1 — Cubic spline through four points (Def 2.3)</source>
            <translation>Ex 2.1 — Spline cúbic per quatre punts (Def 2.3)</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="341" />
            <source>Ex 2.2 — De Casteljau, degree 4</source>
            <translation>Ex 2.2 — De Casteljau, grau 4</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="342" />
            <source>Ex 2.3 — De Casteljau, a closed curve of degree 4</source>
            <translation>Ex 2.3 — De Casteljau, una corba tancada de grau 4</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="343" />
            <source>Ex 2.4 — Bernstein polynomials up to degree 5</source>
            <translation>Ex 2.4 — Polinomis de Bernstein fins al grau 5</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="344" />
            <source>Ex 2.5 — Ex 2.2's curve in the Bernstein basis</source>
            <translation>Ex 2.5 — La corba de l'Ex 2.2 en la base de Bernstein</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="345" />
            <source>Ex 2.6 — Ex 2.3's curve in the Bernstein basis</source>
            <translation>Ex 2.6 — La corba de l'Ex 2.3 en la base de Bernstein</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="346" />
            <source>Ex 2.7 — Least squares, degree 2, uniform parameters</source>
            <translation>Ex 2.7 — Mínims quadrats, grau 2, paràmetres uniformes</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="347" />
            <source>Ex 2.8 — Least squares, degree 3, uniform parameters</source>
            <translation>Ex 2.8 — Mínims quadrats, grau 3, paràmetres uniformes</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="348" />
            <source>Ex 2.9 — Least squares, degree 2, chord lengths</source>
            <translation>Ex 2.9 — Mínims quadrats, grau 2, longituds de corda</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="349" />
            <source>Ex 2.10 — Least squares, degree 3, chord lengths</source>
            <translation>Ex 2.10 — Mínims quadrats, grau 3, longituds de corda</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="350" />
            <source>Ex 2.11 — A Catmull-Rom segment for τ = 0, 1/2, 2</source>
            <translation>Ex 2.11 — Un segment de Catmull-Rom per a τ = 0, 1/2, 2</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="351" />
            <source>Ex 2.12 — Blending functions for several tensions</source>
            <translation>Ex 2.12 — Funcions de mescla per a diverses tensions</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="352" />
            <source>Ex 2.13 — Catmull-Rom curve, cyclic and open</source>
            <translation>Ex 2.13 — Corba de Catmull-Rom, cíclica i oberta</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="356" />
            <source>&amp;Help</source>
            <translation>A&amp;juda</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="357" />
            <source>&amp;User guide</source>
            <translation>&amp;Guia d'ús</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="358" />
            <source>&amp;About Granota</source>
            <translation>&amp;Quant al Granota</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="359" />
            <source>Position of the mouse in the plane</source>
            <translation>Posició del ratolí al pla</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="387" />
            <source>Untitled</source>
            <translation>Sense títol</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="388" />
            <source>%1%2 — Granota</source>
            <translation>%1%2 — Granota</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="395" />
            <source>Unsaved changes</source>
            <translation>Canvis sense desar</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="396" />
            <source>The document has unsaved changes. Save them?</source>
            <translation>El document té canvis sense desar. Els voleu desar?</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="424" />
            <source>Cannot open “%1”: %2</source>
            <translation>No es pot obrir «%1»: %2</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="428" />
            <source>“%1” is too large for a Granota document.</source>
            <translation>«%1» és massa gran per a un document del Granota.</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="450" />
            <source>Cannot write “%1”.</source>
            <translation>No es pot escriure «%1».</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="465" />
            <location filename="../ui/main_window.cpp" line="471" />
            <location filename="../ui/main_window.cpp" line="519" />
            <source>Open document</source>
            <translation>Obre un document</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="466" />
            <source>Granota documents (*.granota);;All files (*)</source>
            <translation>Documents del Granota (*.granota);;Tots els fitxers (*)</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="478" />
            <location filename="../ui/main_window.cpp" line="487" />
            <source>Save document</source>
            <translation>Desa el document</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="479" />
            <source>Granota documents (*.granota)</source>
            <translation>Documents del Granota (*.granota)</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="490" />
            <source>Saved %1</source>
            <translation>S'ha desat %1</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="547" />
            <location filename="../ui/main_window.cpp" line="561" />
            <source>Recover unsaved work</source>
            <translation>Recupera la feina sense desar</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="548" />
            <source>Granota was closed without saving the last changes. Recover them?</source>
            <translation>El Granota es va tancar sense desar els últims canvis. Els voleu recuperar?</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="559" />
            <source>Recovered the unsaved work of the last session.</source>
            <translation>S'ha recuperat la feina sense desar de l'última sessió.</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="561" />
            <source>The autosave could not be read.</source>
            <translation>No s'ha pogut llegir la còpia automàtica.</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="581" />
            <source>No tab is shown.</source>
            <translation>No es mostra cap pestanya.</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="582" />
            <source>Granota — %1</source>
            <translation>Granota — %1</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="593" />
            <source>Unknown export format “%1”.</source>
            <translation>Format d'exportació desconegut: «%1».</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="606" />
            <source>Export PNG</source>
            <translation>Exporta PNG</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="607" />
            <source>Resolution (dots per inch; 300 for print):</source>
            <translation>Resolució (punts per polzada; 300 per imprimir):</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="615" />
            <location filename="../ui/main_window.cpp" line="623" />
            <source>Export</source>
            <translation>Exporta</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="616" />
            <source>%1 files (*.%2)</source>
            <translation>Fitxers %1 (*.%2)</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="621" />
            <source>Exported %1</source>
            <translation>S'ha exportat %1</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="630" />
            <location filename="../ui/main_window.cpp" line="641" />
            <source>Frog animation</source>
            <translation>Animació de la granota</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="630" />
            <source>Number of frames (60 per second):</source>
            <translation>Nombre de fotogrames (60 per segon):</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="634" />
            <source>Folder for the frames</source>
            <translation>Carpeta per als fotogrames</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/main_window.cpp" line="639" />
            <source>Wrote %n frames.</source>
            <translation>
                <numerusform>S'ha escrit %n fotograma.</numerusform>
                <numerusform>S'han escrit %n fotogrames.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="700" />
            <source>User guide</source>
            <translation>Guia d'ús</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="702" />
            <source>&lt;h3&gt;Granota in five tabs&lt;/h3&gt;&lt;p&gt;&lt;b&gt;De Casteljau&lt;/b&gt; (§2.1.1): drag the control points, move t, watch every level.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Bernstein&lt;/b&gt; (§2.1.2): the basis polynomials and their weights at the same t.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Fitting&lt;/b&gt; (§2.1.3): a Bézier curve through data by least squares.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Catmull-Rom&lt;/b&gt; (§2.2): curves through the points, one per tension τ.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Frog&lt;/b&gt; (chapter 4): the soft body, stage by stage.&lt;/p&gt;&lt;p&gt;Double-click to add a point, Delete to remove it, arrows to nudge it, Ctrl+Z to undo. The Examples menu loads every worked example of chapter 2. F11 switches presentation mode.&lt;/p&gt;</source>
            <translation>&lt;h3&gt;El Granota en cinc pestanyes&lt;/h3&gt;&lt;p&gt;&lt;b&gt;De Casteljau&lt;/b&gt; (§2.1.1): arrossegueu els punts de control, moveu t i mireu cada nivell.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Bernstein&lt;/b&gt; (§2.1.2): els polinomis de la base i els seus pesos al mateix t.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Ajust&lt;/b&gt; (§2.1.3): una corba de Bézier que s'ajusta a les dades per mínims quadrats.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Catmull-Rom&lt;/b&gt; (§2.2): corbes que passen pels punts, una per cada tensió τ.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Granota&lt;/b&gt; (capítol 4): el cos tou, etapa a etapa.&lt;/p&gt;&lt;p&gt;Feu doble clic per afegir un punt, Supr per treure'l, les fletxes per moure'l i Ctrl+Z per desfer. El menú Exemples carrega tots els exemples resolts del capítol 2. F11 activa el mode de presentació.&lt;/p&gt;</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="716" />
            <source>About Granota</source>
            <translation>Quant al Granota</translation>
        </message>
        <message>
            <location filename="../ui/main_window.cpp" line="717" />
            <source>&lt;h3&gt;Granota&lt;/h3&gt;&lt;p&gt;Splines and soft bodies for the classroom, from the thesis “Animació procedimental per a cossos tous”.&lt;/p&gt;</source>
            <translation>&lt;h3&gt;Granota&lt;/h3&gt;&lt;p&gt;Corbes i cossos tous per a l'aula, a partir de la tesi «Animació procedimental per a cossos tous».&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Cannot save “%1”: %2. The file on disk is unchanged, and your changes are still here: save them elsewhere (Save As).</source>
            <translation>No es pot desar «%1»: %2. El fitxer del disc no ha canviat, i els vostres canvis encara són aquí: deseu-los en un altre lloc (Desa com a).</translation>
        </message>
        <message>
            <source>Cannot save “%1”: %2. Your changes are still here: save them elsewhere (Save As).</source>
            <translation>No es pot desar «%1»: %2. Els vostres canvis encara són aquí: deseu-los en un altre lloc (Desa com a).</translation>
        </message>
        <message>
            <source>“%1” has changed on disk since this window opened or saved it — in another window or another program. Saving replaces those changes with this window&apos;s.</source>
            <translation>«%1» ha canviat al disc des que aquesta finestra el va obrir o desar — en una altra finestra o un altre programa. Si el deseu, aquells canvis se substitueixen pels d&apos;aquesta finestra.</translation>
        </message>
        <message>
            <source>&amp;Replace it</source>
            <translation>&amp;Substitueix-lo</translation>
        </message>
        <message>
            <source>“%1” already exists. Replace it?</source>
            <translation>«%1» ja existeix. El voleu substituir?</translation>
        </message>
        <message>
            <source>The autosave could not be recovered: %1

It is no longer on disk.</source>
            <translation>No s&apos;ha pogut recuperar la còpia automàtica: %1

Ja no és al disc.</translation>
        </message>
        <message>
            <source>Recovered %1. Not recovered:
%2</source>
            <translation>S&apos;ha recuperat %1. No s&apos;ha recuperat:
%2</translation>
        </message>
        <message>
            <source>Thesis &amp;figures…</source>
            <translation>&amp;Figures de la tesi…</translation>
        </message>
        <message>
            <source>&lt;p&gt;Where a printed example of the thesis slips, the tab says so beside the right value; docs/thesis-errata.md, in Granota&apos;s sources, lists every slip and where Granota shows it.&lt;/p&gt;</source>
            <translation>&lt;p&gt;Quan un exemple imprès de la tesi s&apos;equivoca, la pestanya ho diu al costat del valor correcte; docs/thesis-errata.md, a les fonts del Granota, recull totes les errades i on les mostra el Granota.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>%1 × %2 pixels</source>
            <translation>%1 × %2 píxels</translation>
        </message>
        <message>
            <source>Size of the frames (video):</source>
            <translation>Mida dels fotogrames (vídeo):</translation>
        </message>
        <message>
            <source>&amp;Side panel</source>
            <translation>&amp;Tauler lateral</translation>
        </message>
        <message>
            <source>The settings and results beside the canvas; presentation mode folds them away so that the canvas has the width.</source>
            <translation>Els paràmetres i els resultats al costat del llenç; el mode de presentació els amaga perquè el llenç tingui tota l&apos;amplada.</translation>
        </message>
        <message>
            <source>&amp;Blank the screen</source>
            <translation>Pantalla en &amp;negre</translation>
        </message>
        <message>
            <source>Black over the whole window until B again or a click (a presenter remote&apos;s blank key).</source>
            <translation>Negre sobre tota la finestra fins que torneu a prémer B o feu un clic (la tecla de pantalla en negre d&apos;un comandament de presentacions).</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::PointEditor</name>
        <message>
            <source>Past %1 points the labels are hidden and the handles small, unless this is on.</source>
            <translation>A partir de %1 punts les etiquetes s'amaguen i els marcadors es fan petits, si no s'activa això.</translation>
        </message>
        <message>
            <source>Hide point labels</source>
            <translation>Amaga les etiquetes dels punts</translation>
        </message>
        <message>
            <source>Show point labels</source>
            <translation>Mostra les etiquetes dels punts</translation>
        </message>
        <message numerus="yes">
            <source>%n points: their labels are hidden and their handles small, so that the curve shows; right-click the canvas ▸ Show point labels to see them.</source>
            <translation>
                <numerusform>%n punt: les etiquetes s'amaguen i els marcadors es dibuixen petits perquè es vegi la corba; feu clic amb el botó dret al llenç ▸ Mostra les etiquetes dels punts per veure-les.</numerusform>
                <numerusform>%n punts: les etiquetes s'amaguen i els marcadors es dibuixen petits perquè es vegi la corba; feu clic amb el botó dret al llenç ▸ Mostra les etiquetes dels punts per veure-les.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/point_editor.cpp" line="81" />
            <source>Refused: a point is not a finite number.</source>
            <translation>Refusat: un punt no és un nombre finit.</translation>
        </message>
        <message>
            <location filename="../ui/point_editor.cpp" line="92" />
            <source>Refused: a coordinate must be a finite number.</source>
            <translation>Refusat: una coordenada ha de ser un nombre finit.</translation>
        </message>
        <message>
            <location filename="../ui/point_editor.cpp" line="97" />
            <location filename="../ui/point_editor.cpp" line="264" />
            <source>Move point %1</source>
            <translation>Mou el punt %1</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/point_editor.cpp" line="103" />
            <source>At most %n points here.</source>
            <translation>
                <numerusform>Aquí hi caben com a màxim %n punt.</numerusform>
                <numerusform>Aquí hi caben com a màxim %n punts.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/point_editor.cpp" line="111" />
            <source>Add point</source>
            <translation>Afegeix un punt</translation>
        </message>
        <message numerus="yes">
            <location filename="../ui/point_editor.cpp" line="120" />
            <source>At least %n points are needed here.</source>
            <translation>
                <numerusform>Aquí cal com a mínim %n punt.</numerusform>
                <numerusform>Aquí calen com a mínim %n punts.</numerusform>
            </translation>
        </message>
        <message>
            <location filename="../ui/point_editor.cpp" line="125" />
            <source>Delete point %1</source>
            <translation>Suprimeix el punt %1</translation>
        </message>
        <message>
            <location filename="../ui/point_editor.cpp" line="213" />
            <source>Delete %1%2</source>
            <translation>Suprimeix %1%2</translation>
        </message>
        <message>
            <location filename="../ui/point_editor.cpp" line="215" />
            <source>Add a point here</source>
            <translation>Afegeix un punt aquí</translation>
        </message>
        <message>
            <location filename="../ui/point_editor.cpp" line="218" />
            <source>Snap to grid</source>
            <translation>Ajusta a la quadrícula</translation>
        </message>
        <message>
            <location filename="../ui/point_editor.cpp" line="222" />
            <source>Fit view</source>
            <translation>Encaixa la vista</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::PointTable</name>
        <message>
            <source>Points</source>
            <translation>Punts</translation>
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
            <translation>Els punts com a nombres: escriviu un decimal o una fracció com ara 1/3.</translation>
        </message>
        <message>
            <location filename="../ui/point_table.cpp" line="93" />
            <source>“%1” is not a number: type a decimal (2.5) or a fraction (5/2).</source>
            <translation>«%1» no és un nombre: escriviu un decimal (2,5) o una fracció (5/2).</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::WorkPrecision</name>
        <message>
            <source>points of the polyline (evaluations of the curve)</source>
            <translation>punts de la poligonal (avaluacions de la corba)</translation>
        </message>
        <message>
            <source>uniform t per segment</source>
            <translation>t uniforme per segment</translation>
        </message>
        <message>
            <source>The same number of points on every segment wastes them on the short, gentle ones; adaptive subdivision of each segment puts them where the curve bends and needs fewer for the same error. Both errors fall like 1/N².</source>
            <translation>El mateix nombre de punts a cada segment en malbarata als segments curts i suaus; la subdivisió adaptativa de cada segment els posa on la corba es corba i en necessita menys per al mateix error. Tots dos errors baixen com 1/N².</translation>
        </message>
        <message>
            <source>Against the number of points, both errors fall like 1/N² (twice the points, a quarter of the error), and adaptive subdivision, which puts its points where the curve bends, needs fewer for the same error. Its run time per point is higher: each point costs a flatness test.</source>
            <translation>Respecte del nombre de punts, tots dos errors baixen com 1/N² (el doble de punts, una quarta part de l'error), i la subdivisió adaptativa, que posa els punts on la corba es corba, en necessita menys per al mateix error. El seu temps d'execució per punt és més alt: cada punt costa una prova de planor.</translation>
        </message>
        <message>
            <source>Catmull-Rom sampling: polyline against curve</source>
            <translation>Mostreig de Catmull-Rom: poligonal respecte de la corba</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="28" />
            <source>Curve sampling: polyline against curve</source>
            <translation>Mostreig de corbes: poligonal respecte de la corba</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="30" />
            <source>Evaluating a Bézier curve of degree n</source>
            <translation>Avaluació d'una corba de Bézier de grau n</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="32" />
            <source>Least-squares Bézier fit: normal equations, QR, SVD</source>
            <translation>Ajust de Bézier per mínims quadrats: equacions normals, QR, SVD</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="34" />
            <source>Integrators: global error against run time</source>
            <translation>Integradors: error global segons el temps d'execució</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="36" />
            <source>Soft body: constraint error against substeps</source>
            <translation>Cos tou: error de restriccions segons els subpassos</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="46" />
            <source>De Casteljau and the Bernstein sum stay at rounding level at every degree; Horner on the power basis loses digits as the degree grows, because its coefficients are huge alternating sums that cancel.</source>
            <translation>De Casteljau i la suma de Bernstein es mantenen a nivell d'arrodoniment a tots els graus; Horner en la base de potències perd xifres a mesura que creix el grau, perquè els seus coeficients són sumes alternades enormes que es cancel·len.</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="50" />
            <source>The normal equations square the condition number of M: near degree 25 they have lost almost every digit and by degree 30 the curve is wrong, while QR and SVD still hold about seven digits.</source>
            <translation>Les equacions normals eleven al quadrat el nombre de condició de M: prop del grau 25 han perdut gairebé totes les xifres i al grau 30 la corba ja és errònia, mentre que QR i SVD encara en conserven unes set.</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="54" />
            <source>Halving h halves Euler's error but quarters Verlet's (order 1 against 2): at equal run time Verlet is orders of magnitude more accurate. RK4 (order 4) costs four evaluations per step and wins when high accuracy is needed.</source>
            <translation>Reduir h a la meitat redueix a la meitat l'error d'Euler però a una quarta part el de Verlet (ordre 1 contra 2): amb el mateix temps d'execució, Verlet és ordres de magnitud més precís. RK4 (ordre 4) costa quatre avaluacions per pas i guanya quan cal molta precisió.</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="58" />
            <source>XPBD's constraint error falls as the substeps grow, at a cost proportional to their number; the seed's per-step corrections leave a lasting area deficit.</source>
            <translation>L'error de les restriccions de l'XPBD baixa a mesura que augmenten els subpassos, amb un cost proporcional al seu nombre; les correccions per pas de la llavor deixen un dèficit d'àrea persistent.</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="66" />
            <source>uniform</source>
            <translation>uniforme</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="67" />
            <source>adaptive</source>
            <translation>adaptatiu</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="68" />
            <source>De Casteljau</source>
            <translation>De Casteljau</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="69" />
            <source>Bernstein sum</source>
            <translation>suma de Bernstein</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="70" />
            <source>Horner (power basis)</source>
            <translation>Horner (base de potències)</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="71" />
            <source>normal equations</source>
            <translation>equacions normals</translation>
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
            <translation>Euler explícit</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="75" />
            <source>semi-implicit Euler</source>
            <translation>Euler semiimplícit</translation>
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
            <translation>àrea (XPBD)</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="79" />
            <source>XPBD edge lengths</source>
            <translation>longituds de les arestes (XPBD)</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="80" />
            <source>seed area (Annex II)</source>
            <translation>àrea de la llavor (annex II)</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="91" />
            <source>points</source>
            <translation>punts</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="93" />
            <source>degree</source>
            <translation>grau</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="95" />
            <source>step h</source>
            <translation>pas h</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="97" />
            <source>substeps</source>
            <translation>subpassos</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="104" />
            <source>max distance between curve and polyline</source>
            <translation>distància màxima entre la corba i la poligonal</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="106" />
            <source>max |c(t) − exact| / max |Pᵢ|</source>
            <translation>màx |c(t) − exacte| / màx |Pᵢ|</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="108" />
            <source>max |Pⱼ − Pⱼ(true)| / max |Pⱼ(true)|</source>
            <translation>màx |Pⱼ − Pⱼ(real)| / màx |Pⱼ(real)|</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="110" />
            <source>|x(T) − exact| at T = 10</source>
            <translation>|x(T) − exacte| a T = 10</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="112" />
            <source>RMS relative constraint violation</source>
            <translation>violació relativa de les restriccions (RMS)</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="132" />
            <source>run time per call (s)</source>
            <translation>temps d'execució per crida (s)</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="1" />
            <source>Arc length: Gauss–Legendre, Simpson, polyline</source>
            <translation>Longitud d'arc: Gauss–Legendre, Simpson, poligonal</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="1" />
            <source>The adaptive rule, split at the cusp, reaches rounding level in about two microseconds; one 24-point Gauss rule is off by 1e-3 on the cusp and, repeated on pieces that do not end there, gains only a factor 4 per doubling (the kink, not the rule, sets the pace); Simpson gains 16 per halving, the polyline 4.</source>
            <translation>La regla adaptativa, partida a la cúspide, arriba al nivell de l'arrodoniment en uns dos microsegons; una regla de Gauss de 24 punts s'equivoca en 1e-3 a la cúspide i, repetida en trossos que no hi acaben, només guanya un factor 4 cada cop que es dobla (el punt angulós, no la regla, marca el ritme); Simpson guanya 16 per cada meitat, la poligonal 4.</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="1" />
            <source>adaptive Gauss–Legendre</source>
            <translation>Gauss–Legendre adaptatiu</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="1" />
            <source>Gauss–Legendre 24 points</source>
            <translation>Gauss–Legendre de 24 punts</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="1" />
            <source>Simpson</source>
            <translation>Simpson</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="1" />
            <source>polyline</source>
            <translation>poligonal</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="1" />
            <source>setting (tolerance, pieces, intervals or segments)</source>
            <translation>paràmetre (tolerància, trossos, intervals o segments)</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_plot.cpp" line="1" />
            <source>max relative error of L over four curves, one with a cusp</source>
            <translation>error relatiu màxim de L en quatre corbes, una amb una cúspide</translation>
        </message>
        <message>
            <source>Energy drift: E/E₀ − 1 over 10⁵ steps of x″ = −x</source>
            <translation>Deriva d&apos;energia: E/E₀ − 1, 10⁵ passos de x″ = −x</translation>
        </message>
        <message>
            <source>Explicit Euler multiplies the energy by 1 + h² every step: it grows without bound (×2·10⁴ after 10³ steps). RK4 loses the same tiny fraction every step (1.4·10⁻⁸ at h = 0.1), a drift that grows linearly (−1.39·10⁻³ after 10⁵ steps). Semi-implicit Euler and Verlet are symplectic: each keeps a modified energy exactly (x² + v² − h x v; v² + (1 − h²/4) x²), so their error stays bounded however long the run, about h/2 and h²/4.</source>
            <translation>Euler explícit multiplica l&apos;energia per 1 + h² a cada pas: creix sense límit (×2·10⁴ després de 10³ passos). RK4 perd la mateixa fracció minúscula a cada pas (1,4·10⁻⁸ amb h = 0,1), una deriva que creix linealment (−1,39·10⁻³ després de 10⁵ passos). Euler semiimplícit i Verlet són simplèctics: cadascun conserva exactament una energia modificada (x² + v² − h x v; v² + (1 − h²/4) x²), de manera que el seu error es manté fitat per llarga que sigui l&apos;execució, al voltant de h/2 i h²/4.</translation>
        </message>
        <message>
            <source>Verlet (Annex II start)</source>
            <translation>Verlet (inici de l&apos;annex II)</translation>
        </message>
        <message>
            <source>step n</source>
            <translation>pas n</translation>
        </message>
        <message>
            <source>|E/E₀ − 1|, E = (v² + x²)/2</source>
            <translation>|E/E₀ − 1|, amb E = (v² + x²)/2</translation>
        </message>
        <message>
            <source>Bézier extraction + De Casteljau</source>
            <translation>extracció de Bézier + De Casteljau</translation>
        </message>
        <message>
            <source>Evaluating a B-spline curve of degree p</source>
            <translation>Avaluació d&apos;una corba B-spline de grau p</translation>
        </message>
        <message>
            <source>basis functions × points</source>
            <translation>funcions de base × punts</translation>
        </message>
        <message>
            <source>de Boor</source>
            <translation>de Boor</translation>
        </message>
        <message>
            <source>de Boor&apos;s algorithm, the Bézier segments with De Casteljau and the basis functions times the points all stay at rounding level at every degree: each is a chain of convex combinations. The Bézier segments, extracted once, are the quickest per point (one ratio t instead of p(p + 1)/2 ratios of knots) but carry the rounding of their extraction, up to a few times de Boor&apos;s error; the basis sum is the slowest.</source>
            <translation>L&apos;algorisme de De Boor, els segments de Bézier amb De Casteljau i les funcions de base per punts es mantenen tots al nivell de l&apos;arrodoniment a tots els graus: cadascun és una cadena de combinacions convexes. Els segments de Bézier, extrets una sola vegada, són els més ràpids per punt (una raó t en lloc de p(p + 1)/2 raons de nusos), però porten l&apos;arrodoniment de l&apos;extracció, fins a unes quantes vegades l&apos;error de De Boor; la suma de funcions de base és la més lenta.</translation>
        </message>
        <message>
            <source>max |c(u) − exact| / max |Pᵢ|</source>
            <translation>màx |c(u) − exacte| / màx |Pᵢ|</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::WorkPrecisionPanel</name>
        <message>
            <source>Work-precision plot: each marker is one setting of a method; lower is more accurate, left is cheaper (faster, or fewer points).</source>
            <translation>Gràfic de treball-precisió: cada marca és un valor del paràmetre d'un mètode; més avall és més precís, més a l'esquerra és més barat (més ràpid, o menys punts).</translation>
        </message>
        <message>
            <source>Press Measure: each method runs over a range of its setting, and the plot shows its error against its run time or against the setting itself (lower left is better).</source>
            <translation>Premeu Mesura: cada mètode s'executa amb tot un ventall de valors del seu paràmetre, i el gràfic en mostra l'error respecte del temps d'execució o del mateix paràmetre (com més avall i a l'esquerra, millor).</translation>
        </message>
        <message>
            <source>The x axis: the run time per call, or the method's setting itself (the number of points, the degree, the step…), which counts the cost without the clock.</source>
            <translation>L'eix x: el temps d'execució per crida, o el mateix paràmetre del mètode (el nombre de punts, el grau, el pas…), que compta el cost sense rellotge.</translation>
        </message>
        <message>
            <source>against the setting</source>
            <translation>respecte del paràmetre</translation>
        </message>
        <message>
            <source>against %1</source>
            <translation>respecte de: %1</translation>
        </message>
        <message>
            <source>against run time</source>
            <translation>respecte del temps d'execució</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_panel.cpp" line="120" />
            <source>Cancelled. Press Measure to start again.</source>
            <translation>S'ha cancel·lat. Premeu Mesura per tornar a començar.</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_panel.cpp" line="142" />
            <source>Which numerical method to measure: its error against its run time.</source>
            <translation>Quin mètode numèric es mesura: el seu error respecte del seu temps d'execució.</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_panel.cpp" line="143" />
            <source>Measure</source>
            <translation>Mesura</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_panel.cpp" line="144" />
            <source>Run every method over a range of its setting and plot error against run time.</source>
            <translation>Executa cada mètode amb un ventall de valors del seu paràmetre i dibuixa l'error respecte del temps d'execució.</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_panel.cpp" line="145" />
            <source>Cancel</source>
            <translation>Cancel·la</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_panel.cpp" line="146" />
            <source>Stop the measurement.</source>
            <translation>Atura la mesura.</translation>
        </message>
        <message>
            <location filename="../ui/work_precision_panel.cpp" line="147" />
            <source>Measuring…</source>
            <translation>Mesurant…</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::UserFile</name>
        <message>
            <source>it cannot be read.</source>
            <translation>no es pot llegir.</translation>
        </message>
        <message>
            <source>Cannot open “%1”: %2</source>
            <translation>No es pot obrir «%1»: %2</translation>
        </message>
        <message>
            <source>“%1” is a folder, not a file.</source>
            <translation>«%1» és una carpeta, no un fitxer.</translation>
        </message>
        <message>
            <source>“%1” is larger than %2 MB, the most Granota reads from one file.</source>
            <translation>«%1» ocupa més de %2 MB, el màxim que el Granota llegeix d'un fitxer.</translation>
        </message>
        <message>
            <source>there is no space left on the disk</source>
            <translation>no queda espai al disc</translation>
        </message>
        <message>
            <source>your disk quota is full</source>
            <translation>la vostra quota de disc és plena</translation>
        </message>
        <message>
            <source>the disk is read-only</source>
            <translation>el disc és només de lectura</translation>
        </message>
        <message>
            <source>you do not have permission</source>
            <translation>no teniu permís</translation>
        </message>
        <message>
            <source>it does not exist</source>
            <translation>no existeix</translation>
        </message>
        <message>
            <source>a folder on its path does not exist</source>
            <translation>una carpeta del camí no existeix</translation>
        </message>
        <message>
            <source>it is a folder</source>
            <translation>és una carpeta</translation>
        </message>
        <message>
            <source>the name is too long</source>
            <translation>el nom és massa llarg</translation>
        </message>
        <message>
            <source>the file would be too large for the disk</source>
            <translation>el fitxer seria massa gran per al disc</translation>
        </message>
        <message>
            <source>the disk reported an error</source>
            <translation>el disc ha informat d&apos;un error</translation>
        </message>
        <message>
            <source>too many files are open</source>
            <translation>hi ha massa fitxers oberts</translation>
        </message>
        <message>
            <source>the file is in use</source>
            <translation>el fitxer és en ús</translation>
        </message>
        <message>
            <source>the system refused it (error %1)</source>
            <translation>el sistema ho ha refusat (error %1)</translation>
        </message>
        <message>
            <source>“%1” is a pipe or a device, not a file.</source>
            <translation>«%1» és una canonada o un dispositiu, no un fitxer.</translation>
        </message>
        <message>
            <source>Cannot open “%1”: %2.</source>
            <translation>No es pot obrir «%1»: %2.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::Autosave</name>
        <message>
            <source>Cannot write the autosave “%1”: %2</source>
            <translation>No es pot escriure la còpia automàtica «%1»: %2</translation>
        </message>
        <message>
            <source>Cannot write the autosave “%1”: %2.</source>
            <translation>No es pot escriure la còpia automàtica «%1»: %2.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::CurveCanvas</name>
        <message>
            <source>These points are too large to draw: the canvas shows coordinates up to about ±%1. Their values are in the table; bring them closer to the origin to see the curve.</source>
            <translation>Aquests punts són massa grans per dibuixar-los: el llenç mostra coordenades fins a uns ±%1. Els seus valors són a la taula; acosteu-los a l'origen per veure la corba.</translation>
        </message>
    </context>
    <context>
        <name>granota::CommandLine</name>
        <message>
            <source>bad body “%1” (1 … %2)</source>
            <translation>cos «%1» incorrecte (1 … %2)</translation>
        </message>
        <message>
            <source>--plot-body: the scene has no bodies to choose from (it needs two or more)</source>
            <translation>--plot-body: l'escena no té cossos per triar (en calen dos o més)</translation>
        </message>
        <message>
            <source>Plot body K (1, 2, …) of the frog's scene alone, marked on the canvas.</source>
            <translation>Dibuixa només el cos K (1, 2, …) de l'escena de la granota, marcat al llenç.</translation>
        </message>
        <message>
            <source>bad size “%1” (WxH, e.g. 800x570)</source>
            <translation>mida «%1» incorrecta (AxB, p. ex. 800x570)</translation>
        </message>
        <message>
            <source>Window size WxH (a screenshot's, else the window's), e.g. 800x570.</source>
            <translation>Mida de la finestra AxB (la de la captura o, si no, la de la finestra), p. ex. 800x570.</translation>
        </message>
        <message>
            <source>cannot write “%1”</source>
            <translation>no es pot escriure «%1»</translation>
        </message>
        <message>
            <source>unknown tab “%1” (decasteljau, bernstein, fit, catmull-rom, frog, bspline)</source>
            <translation>pestanya desconeguda «%1» (decasteljau, bernstein, fit, catmull-rom, frog, bspline)</translation>
        </message>
        <message>
            <source>unknown example “%1” (2.1 … 2.13)</source>
            <translation>exemple desconegut «%1» (2.1 … 2.13)</translation>
        </message>
        <message>
            <source>cannot make a scratch folder for the screenshot run</source>
            <translation>no es pot crear una carpeta temporal per a la captura</translation>
        </message>
        <message>
            <source>unknown language “%1” (ca, en)</source>
            <translation>idioma desconegut «%1» (ca, en)</translation>
        </message>
        <message>
            <source>A .granota document to open.</source>
            <translation>Un document .granota per obrir.</translation>
        </message>
        <message>
            <source>Render the window (1280x800) to FILE.png and exit.</source>
            <translation>Dibuixa la finestra (1280x800) a FILE.png i surt.</translation>
        </message>
        <message>
            <source>Start in presentation mode.</source>
            <translation>Comença en mode de presentació.</translation>
        </message>
        <message>
            <source>Open the frog tab on scene NAME.</source>
            <translation>Obre la pestanya Granota a l'escena NAME.</translation>
        </message>
        <message>
            <source>Load worked example ID (2.1 … 2.13).</source>
            <translation>Carrega l'exemple resolt ID (2.1 … 2.13).</translation>
        </message>
        <message>
            <source>Interface language: ca or en.</source>
            <translation>Idioma de la interfície: ca o en.</translation>
        </message>
        <message>
            <source>Open on tab KEY: decasteljau, bernstein, fit, catmull-rom, frog, bspline.</source>
            <translation>Obre a la pestanya KEY: decasteljau, bernstein, fit, catmull-rom, frog, bspline.</translation>
        </message>
        <message>
            <source>Splines and soft bodies, for the classroom.</source>
            <translation>Splines i cossos tous, per a l'aula.</translation>
        </message>
        <message>
            <source>List the thesis&apos;s figures: number, variants, caption; and exit.</source>
            <translation>Llista les figures de la tesi: número, variants i peu; i surt.</translation>
        </message>
        <message>
            <source>Draw the thesis&apos;s figure N (2.1 … 4.13), with --export.</source>
            <translation>Dibuixa la figura N de la tesi (2.1 … 4.13), amb --export.</translation>
        </message>
        <message>
            <source>The figure&apos;s variant V (--list-figures names them).</source>
            <translation>La variant V de la figura (--list-figures les anomena).</translation>
        </message>
        <message>
            <source>Write the figure&apos;s view alone to FILE (.svg, .pdf, .png, .tex or .csv) and exit.</source>
            <translation>Escriu només la vista de la figura a FITXER (.svg, .pdf, .png, .tex o .csv) i surt.</translation>
        </message>
        <message>
            <source>Resolution of a PNG export, 24 … 1200 (96: one pixel per pixel).</source>
            <translation>Resolució d&apos;una exportació PNG, 24 … 1200 (96: un píxel per píxel).</translation>
        </message>
        <message>
            <source>--figure N and --export FILE go together (--variant and --dpi with them)</source>
            <translation>--figure N i --export FITXER van junts (--variant i --dpi amb ells)</translation>
        </message>
        <message>
            <source>unknown figure “%1” (2.1 … 2.10, 4.1 … 4.13; --list-figures)</source>
            <translation>figura desconeguda «%1» (2.1 … 2.10, 4.1 … 4.13; --list-figures)</translation>
        </message>
        <message>
            <source>Fig %1 has no variant “%2” (%3)</source>
            <translation>la Fig. %1 no té la variant «%2» (%3)</translation>
        </message>
        <message>
            <source>cannot tell the format of “%1”: end it in .svg, .pdf, .png, .tex or .csv</source>
            <translation>no se sap el format de «%1»: acabeu-lo en .svg, .pdf, .png, .tex o .csv</translation>
        </message>
        <message>
            <source>bad resolution “%1” (24 … 1200)</source>
            <translation>resolució incorrecta «%1» (24 … 1200)</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::CurveTab</name>
        <message>
            <source>“pointLabels” is not true or false.</source>
            <translation>«pointLabels» no és ni true ni false.</translation>
        </message>
        <message>
            <source>Keys: ] and [ select a point, the arrows nudge it (Shift: ten times more), Delete removes it; Tab leaves the canvas.</source>
            <translation>Tecles: ] i [ seleccionen un punt, les fletxes el mouen una mica (Maj: deu vegades més), Supr l&apos;elimina; Tab surt del llenç.</translation>
        </message>
        <message>
            <source>“exactPoints” is not a list of [x, y] pairs, one for each point.</source>
            <translation>“exactPoints” no és una llista de parells [x, y], un per a cada punt.</translation>
        </message>
        <message>
            <source>“exactPoints” entry %1 is not a pair of exact values of point %1 (fractions such as “1/3”, or null).</source>
            <translation>L&apos;entrada %1 de “exactPoints” no és un parell de valors exactes del punt %1 (fraccions com ara “1/3”, o null).</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::TikzOptionsDialog</name>
        <message>
            <source>The defaults fit a beamer frame; the picture needs \usepackage{tikz}.</source>
            <translation>Els valors per defecte caben en una diapositiva de beamer; la figura necessita \usepackage{tikz}.</translation>
        </message>
        <message>
            <source>Height at most:</source>
            <translation>Altura màxima:</translation>
        </message>
        <message>
            <source>Width:</source>
            <translation>Amplada:</translation>
        </message>
        <message>
            <source>Grid</source>
            <translation>Quadrícula</translation>
        </message>
        <message>
            <source>Axes with tick labels</source>
            <translation>Eixos amb marques i valors</translation>
        </message>
        <message>
            <source>Height at most</source>
            <translation>Altura màxima</translation>
        </message>
        <message>
            <source>A taller picture is made smaller until it is this tall. %1 cm fits a beamer frame with a title.</source>
            <translation>Una figura més alta es redueix fins a tenir aquesta altura. %1 cm caben en una diapositiva de beamer amb títol.</translation>
        </message>
        <message>
            <source>Width</source>
            <translation>Amplada</translation>
        </message>
        <message>
            <source>The picture's width on the page, labels included. %1 cm fits a beamer frame.</source>
            <translation>L'amplada de la figura a la pàgina, amb les etiquetes. %1 cm caben en una diapositiva de beamer.</translation>
        </message>
        <message>
            <source>TikZ picture</source>
            <translation>Figura TikZ</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::ShortcutsHelp</name>
        <message>
            <source>Frog tab (P, S, the comma and the period, R, M, [ and ] whenever the tab is shown, unless a field is being typed in)</source>
            <translation>Pestanya Granota (P, S, la coma i el punt, R, M, [ i ] sempre que es mostra la pestanya, tret que s'estigui escrivint en un camp)</translation>
        </message>
        <message>
            <source>Stopwatch: mark the step shown, or clear the mark</source>
            <translation>Cronòmetre: marca el pas que es mostra, o esborra la marca</translation>
        </message>
        <message>
            <source>M</source>
            <translation>M</translation>
        </message>
        <message>
            <source>One step back in the recorded run (pausing first)</source>
            <translation>Un pas enrere en l'execució enregistrada (aturant-la abans)</translation>
        </message>
        <message>
            <source>,</source>
            <translation>,</translation>
        </message>
        <message>
            <source>Slower and faster (⅛× to 4×)</source>
            <translation>Més lent i més ràpid (de ⅛× a 4×)</translation>
        </message>
        <message>
            <source>[ and ]</source>
            <translation>[ i ]</translation>
        </message>
        <message>
            <source>Alt+arrows (Shift: ten times more)</source>
            <translation>Alt+fletxes (Maj: deu vegades més)</translation>
        </message>
        <message>
            <source>De Casteljau: mold the curve at t, c(t) moving by the same step</source>
            <translation>De Casteljau: modela la corba a t; c(t) es mou el mateix pas</translation>
        </message>
        <message>
            <source>De Casteljau, Fitting and Catmull-Rom canvases</source>
            <translation>Llenços de De Casteljau, Ajust i Catmull-Rom</translation>
        </message>
        <message>
            <source>The window</source>
            <translation>La finestra</translation>
        </message>
        <message>
            <source>On the canvas: a new body at the cursor, held until released</source>
            <translation>Al llenç: un cos nou al cursor, agafat fins que es deixa anar la tecla</translation>
        </message>
        <message>
            <source>Space</source>
            <translation>Espai</translation>
        </message>
        <message>
            <source>On the canvas: let go, or clear the ruler</source>
            <translation>Al llenç: el deixa anar, o esborra el regle</translation>
        </message>
        <message>
            <source>Esc</source>
            <translation>Esc</translation>
        </message>
        <message>
            <source>On the canvas: grab the body at the cursor (or the nearest one), again to let go</source>
            <translation>Al llenç: agafa el cos que hi ha al cursor (o el més proper); un altre cop, el deixa anar</translation>
        </message>
        <message>
            <source>G or Enter</source>
            <translation>G o Retorn</translation>
        </message>
        <message>
            <source>On the canvas: move the keyboard cursor, and what it holds</source>
            <translation>Al llenç: mou el cursor del teclat, i el que agafa</translation>
        </message>
        <message>
            <source>Arrows (Shift: five times further)</source>
            <translation>Fletxes (Maj: cinc vegades més lluny)</translation>
        </message>
        <message>
            <source>Reset the scene</source>
            <translation>Reinicia l'escena</translation>
        </message>
        <message>
            <source>R</source>
            <translation>R</translation>
        </message>
        <message>
            <source>One step (pausing first)</source>
            <translation>Un pas (primer fa una pausa)</translation>
        </message>
        <message>
            <source>S or .</source>
            <translation>S o .</translation>
        </message>
        <message>
            <source>Pause and run</source>
            <translation>Pausa i continua</translation>
        </message>
        <message>
            <source>P</source>
            <translation>P</translation>
        </message>
        <message>
            <source>Remove the selected point</source>
            <translation>Elimina el punt seleccionat</translation>
        </message>
        <message>
            <source>Delete, Backspace</source>
            <translation>Supr, Retrocés</translation>
        </message>
        <message>
            <source>Nudge the selected point by a round step</source>
            <translation>Desplaça el punt seleccionat un pas rodó</translation>
        </message>
        <message>
            <source>Arrows (Shift: ten times more)</source>
            <translation>Fletxes (Maj: deu vegades més)</translation>
        </message>
        <message>
            <source>Select the next or the previous point</source>
            <translation>Selecciona el punt següent o l'anterior</translation>
        </message>
        <message>
            <source>] and [</source>
            <translation>] i [</translation>
        </message>
        <message>
            <source>Move the focus into and out of the canvas, to the next or previous control</source>
            <translation>Porta el focus al llenç i el treu cap al control següent o l'anterior</translation>
        </message>
        <message>
            <source>Tab, Shift+Tab</source>
            <translation>Tab, Maj+Tab</translation>
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
            <translation>Al llenç: un regle des del cursor; les fletxes el mouen i L un altre cop el fixa</translation>
        </message>
        <message>
            <source>Right drag, or Ctrl+drag</source>
            <translation>Arrossegament amb el botó dret, o Ctrl+arrossegament</translation>
        </message>
        <message>
            <source>On the canvas: measure in px with the ruler</source>
            <translation>Al llenç: mesura en px amb el regle</translation>
        </message>
        <message>
            <source>Catmull-Rom, Hermite family: move the selected point&apos;s tangent by 1/10</source>
            <translation>Catmull-Rom, família d&apos;Hermite: mou la tangent del punt seleccionat 1/10</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::ExactPanel</name>
        <message>
            <source>Exact computation</source>
            <translation>Càlcul exacte</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::DeCasteljauCurveDrag</name>
        <message>
            <source>Refused: a coordinate must be a finite number.</source>
            <translation>Refusat: una coordenada ha de ser un nombre finit.</translation>
        </message>
        <message>
            <source>c(t) at t = %1 moved by %2: the control points changed the least that does it.</source>
            <translation>c(t) a t = %1 s'ha mogut %2: els punts de control han canviat el mínim que cal.</translation>
        </message>
        <message>
            <source>Mold the curve at t = %1</source>
            <translation>Modela la corba a t = %1</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::CurvatureCombScaleBox</name>
        <message>
            <source>automatic</source>
            <translation>automàtica</translation>
        </message>
        <message>
            <source>The comb's scale: a tooth is |κ| × this long (in the curve's units). Automatic: the 90th percentile of |κ| gives teeth 15 % of the control polygon's size, and the teeth rescale as the curve changes; a number keeps them comparable. 0 is automatic.</source>
            <translation>L'escala de la pinta: una pua fa |κ| × aquest valor (en les unitats de la corba). Automàtica: el percentil 90 de |κ| dona pues del 15 % de la mida del polígon de control, i les pues es reescalen quan la corba canvia; un nombre les manté comparables. 0 és automàtica.</translation>
        </message>
        <message>
            <source>Comb scale</source>
            <translation>Escala de la pinta</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::FrogPlotPanel</name>
        <message>
            <source>Whose values to plot: all the bodies summed (the area error: their mean; the stretch: the largest), or one body alone, with the legs that hang from it. The canvas marks the body chosen. The CSV holds what is plotted.</source>
            <translation>De qui es dibuixen els valors: tots els cossos sumats (l'error d'àrea: la mitjana; l'estirament: el màxim), o un sol cos, amb les potes que en pengen. El llenç marca el cos triat. El CSV conté el que es dibuixa.</translation>
        </message>
        <message>
            <source>Body %1 alone: its values are kept from the next step on.</source>
            <translation>Només el cos %1: se'n guarden els valors a partir del pas següent.</translation>
        </message>
        <message>
            <source>Body %1 alone: its values are kept from %2 s on.</source>
            <translation>Només el cos %1: se'n guarden els valors a partir de %2 s.</translation>
        </message>
        <message>
            <source>Body %1</source>
            <translation>Cos %1</translation>
        </message>
        <message>
            <source>All bodies</source>
            <translation>Tots els cossos</translation>
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
            <translation>temps (s)</translation>
        </message>
        <message>
            <source>damping</source>
            <translation>esmorteïment</translation>
        </message>
        <message>
            <source>other losses</source>
            <translation>altres pèrdues</translation>
        </message>
        <message>
            <source>link %1</source>
            <translation>segment %1</translation>
        </message>
        <message>
            <source>largest stretch</source>
            <translation>estirament màxim</translation>
        </message>
        <message>
            <source>kinetic</source>
            <translation>cinètica</translation>
        </message>
        <message>
            <source>gravitational</source>
            <translation>gravitatòria</translation>
        </message>
        <message>
            <source>elastic</source>
            <translation>elàstica</translation>
        </message>
        <message>
            <source>dθ/dt (rad/step)</source>
            <translation>dθ/dt (rad/pas)</translation>
        </message>
        <message>
            <source>contacts</source>
            <translation>contactes</translation>
        </message>
        <message>
            <source>area error</source>
            <translation>error d’àrea</translation>
        </message>
        <message>
            <source>area error (%)</source>
            <translation>error d’àrea (%)</translation>
        </message>
        <message>
            <source>angle θ from the vertical (rad)</source>
            <translation>angle θ des de la vertical (rad)</translation>
        </message>
        <message>
            <source>What to plot against time: the energies and what damping and the rest took, the area error, the largest stretch, the contacts; or, for the pendulums, each link's angle against its angular velocity. The wheel zooms the window of seconds.</source>
            <translation>Què es representa en el temps: les energies i el que s’han endut l’esmorteïment i la resta, l’error d’àrea, l’estirament màxim, els contactes; o, per als pèndols, l’angle de cada segment contra la seva velocitat angular. La roda del ratolí amplia o redueix la finestra de segons.</translation>
        </message>
        <message>
            <source>Energies in px²/step², unit masses. The seed's springs and area are corrections, not forces: it stores no elastic energy and books no losses; total = kinetic + gravitational.</source>
            <translation>Energies en px²/pas², masses unitàries. Els molls i l’àrea de la llavor són correccions, no forces: no desa energia elàstica ni comptabilitza pèrdues; total = cinètica + gravitatòria.</translation>
        </message>
        <message>
            <source>Plots over time</source>
            <translation>Gràfics en el temps</translation>
        </message>
        <message>
            <source>Phase plot of the last %1 s: each link's orbit; a small swing of a free link is an ellipse, with the period 2π√(L/g).</source>
            <translation>Diagrama de fases dels darrers %1 s: l’òrbita de cada segment; una oscil·lació petita d’un segment lliure és una el·lipse, de període 2π√(L/g).</translation>
        </message>
        <message>
            <source>Phase plot of the last %1 s: each link's orbit. The dashed lines are the first link's limits (§4.15): an orbit that reaches one is cut off.</source>
            <translation>Diagrama de fases dels darrers %1 s: l’òrbita de cada segment. Les línies discontínues són els límits del primer segment (§4.15): una òrbita que n’arriba a un queda tallada.</translation>
        </message>
        <message>
            <source>Phase plot (pendulums)</source>
            <translation>Diagrama de fases (pèndols)</translation>
        </message>
        <message>
            <source>Energies in mass·px²/step². Other losses: hits and friction at walls and between bodies, and the solver's own dissipation, less what the mouse put in.</source>
            <translation>Energies en massa·px²/pas². Altres pèrdues: xocs i fregament a les parets i entre cossos, i la dissipació pròpia del mètode, menys el que hi ha posat el ratolí.</translation>
        </message>
        <message>
            <source>Largest stretch</source>
            <translation>Estirament màxim</translation>
        </message>
        <message>
            <source>Exported %1</source>
            <translation>S’ha exportat %1</translation>
        </message>
        <message>
            <source>Export the series</source>
            <translation>Exporta les sèries</translation>
        </message>
        <message>
            <source>Export CSV…</source>
            <translation>Exporta CSV…</translation>
        </message>
        <message>
            <source>Every step kept (the last %1 minutes), in the columns of granota-cli simulate --series.</source>
            <translation>Tots els passos desats (els darrers %1 minuts), amb les columnes de granota-cli simulate --series.</translation>
        </message>
        <message>
            <source>Energy</source>
            <translation>Energia</translation>
        </message>
        <message>
            <source>energy</source>
            <translation>energia</translation>
        </message>
        <message>
            <source>Contacts</source>
            <translation>Contactes</translation>
        </message>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>Fitxers CSV (*.csv)</translation>
        </message>
        <message>
            <source>Area error</source>
            <translation>Error d’àrea</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::ThesisFigures</name>
        <message>
            <source>Fig %1 — %2</source>
            <translation>Fig. %1 — %2</translation>
        </message>
        <message>
            <source>Fig %1</source>
            <translation>Fig. %1</translation>
        </message>
        <message>
            <source>Fig %1 names no tab of Granota.</source>
            <translation>La Fig. %1 no correspon a cap pestanya del Granota.</translation>
        </message>
        <message>
            <source>Fig %1 could not be shown.</source>
            <translation>No s&apos;ha pogut mostrar la Fig. %1.</translation>
        </message>
        <message>
            <source>Fig %1 could not be shown: %2</source>
            <translation>No s&apos;ha pogut mostrar la Fig. %1: %2</translation>
        </message>
        <message>
            <source>Unknown export format “%1” (svg, pdf, png, tex, csv).</source>
            <translation>Format d&apos;exportació desconegut «%1» (svg, pdf, png, tex, csv).</translation>
        </message>
        <message>
            <source>as defined</source>
            <translation>segons la definició</translation>
        </message>
        <message>
            <source>as the thesis computed it</source>
            <translation>com la va calcular la tesi</translation>
        </message>
        <message>
            <source>every degree</source>
            <translation>tots els graus</translation>
        </message>
        <message>
            <source>(a) at rest</source>
            <translation>(a) en repòs</translation>
        </message>
        <message>
            <source>(b) grabbed</source>
            <translation>(b) agafada</translation>
        </message>
        <message>
            <source>degree n = %1</source>
            <translation>grau n = %1</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::ThesisFiguresDialog</name>
        <message numerus="yes">
            <source>Showing Fig %1 replaces the Frog tab&apos;s run of %n step(s), which cannot be undone. Show it?</source>
            <translation>
                <numerusform>Mostrar la Fig. %1 substitueix l&apos;execució de %n pas de la pestanya Granota, que no es pot desfer. La voleu mostrar?</numerusform>
                <numerusform>Mostrar la Fig. %1 substitueix l&apos;execució de %n passos de la pestanya Granota, que no es pot desfer. La voleu mostrar?</numerusform>
            </translation>
        </message>
        <message>
            <source>Thesis figures</source>
            <translation>Figures de la tesi</translation>
        </message>
        <message>
            <source>&amp;Variant:</source>
            <translation>&amp;Variant:</translation>
        </message>
        <message>
            <source>&amp;Show</source>
            <translation>&amp;Mostra</translation>
        </message>
        <message>
            <source>&amp;Export…</source>
            <translation>&amp;Exporta…</translation>
        </message>
        <message>
            <source>Close</source>
            <translation>Tanca</translation>
        </message>
        <message>
            <source>It has no tab of its own: Export… writes it.</source>
            <translation>No té pestanya pròpia: Exporta… l&apos;escriu.</translation>
        </message>
        <message>
            <source>Export figure</source>
            <translation>Exporta la figura</translation>
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
            <translation>el punt %1 és %2, no dos nombres: escriviu «x,y» amb punts decimals, «x;y» amb comes decimals (com ho desa un full de càlcul en català) o x i y separats per un tabulador; un punt per línia.</translation>
        </message>
        <message>
            <source>point %1: %2 is %3 characters long, more than %4, the longest number Granota reads.</source>
            <translation>punt %1: %2 té %3 caràcters, més de %4, el nombre més llarg que llegeix Granota.</translation>
        </message>
        <message>
            <source>point %1: %2 = %3 is not a number (write integers, decimals or fractions p/q).</source>
            <translation>punt %1: %2 = %3 no és un nombre (escriviu enters, decimals o fraccions p/q).</translation>
        </message>
        <message>
            <source>point %1: %2 = %3 is too large (the largest double is about 1.8e308).</source>
            <translation>punt %1: %2 = %3 és massa gran (el double més gran és d&apos;uns 1,8e308).</translation>
        </message>
        <message>
            <source>point %1: %2 = %3 is too close to zero to read.</source>
            <translation>punt %1: %2 = %3 és massa a prop de zero per llegir-lo.</translation>
        </message>
        <message>
            <source>No points were given.</source>
            <translation>No s&apos;ha donat cap punt.</translation>
        </message>
        <message>
            <source>The file holds no points.</source>
            <translation>El fitxer no conté cap punt.</translation>
        </message>
        <message>
            <source>There are more than %1 points, the most Granota reads.</source>
            <translation>Hi ha més de %1 punts, el màxim que llegeix Granota.</translation>
        </message>
        <message>
            <source>The text is not a JSON list of points [[x,y],…].</source>
            <translation>El text no és una llista JSON de punts [[x,y],…].</translation>
        </message>
        <message>
            <source>The JSON text is %1, not a list of points [[x,y],…].</source>
            <translation>El text JSON és %1, no una llista de punts [[x,y],…].</translation>
        </message>
        <message>
            <source>JSON point %1 is %2, not a pair [x,y].</source>
            <translation>El punt JSON %1 és %2, no un parell [x,y].</translation>
        </message>
        <message>
            <source>The scene has no parameter %1.</source>
            <translation>L&apos;escena no té el paràmetre %1.</translation>
        </message>
        <message>
            <source>“%1” must be a whole number.</source>
            <translation>«%1» ha de ser un nombre enter.</translation>
        </message>
        <message>
            <source>“%1” must be from %2 to %3.</source>
            <translation>«%1» ha d&apos;anar de %2 a %3.</translation>
        </message>
        <message>
            <source>“%1” must be a number.</source>
            <translation>«%1» ha de ser un nombre.</translation>
        </message>
        <message>
            <source>“%1” must be a pair of numbers x, y.</source>
            <translation>«%1» ha de ser un parell de nombres x, y.</translation>
        </message>
        <message>
            <source>“%1” must be a finite number.</source>
            <translation>«%1» ha de ser un nombre finit.</translation>
        </message>
        <message>
            <source>“%1” must be a finite number ≥ 0.</source>
            <translation>«%1» ha de ser un nombre finit ≥ 0.</translation>
        </message>
        <message>
            <source>“%1” must be at most 1e15 in magnitude.</source>
            <translation>«%1» ha de ser com a màxim 1e15 en valor absolut.</translation>
        </message>
        <message>
            <source>A body needs at least 3 sides (a polygon), not %1.</source>
            <translation>Un cos necessita almenys 3 costats (un polígon), no %1.</translation>
        </message>
        <message>
            <source>A body has at most %2 sides, not %1.</source>
            <translation>Un cos té com a màxim %2 costats, no %1.</translation>
        </message>
        <message>
            <source>The frame must be at least 1 × 1 px.</source>
            <translation>El marc ha de fer almenys 1 × 1 px.</translation>
        </message>
        <message>
            <source>Bodies × sides must be at most %1 vertices in all: lower the bodies or the sides.</source>
            <translation>Cossos × costats han de ser com a màxim %1 vèrtexs en total: reduïu els cossos o els costats.</translation>
        </message>
        <message>
            <source>A Bézier outline of degree %1 sampled at %2 points costs %3 interpolations, more than %4: lower the sides or the Bézier samples.</source>
            <translation>Una silueta de Bézier de grau %1 mostrejada en %2 punts costa %3 interpolacions, més de %4: reduïu els costats o les mostres de Bézier.</translation>
        </message>
        <message>
            <source>%1 bodies of radius %2 px do not fit side by side in a %3 × %4 px frame, and piled up their %5 vertices would all touch (at most %6 may start piled): lower the bodies, the sides or the radius, or widen the frame.</source>
            <translation>%1 cossos de radi %2 px no caben l&apos;un al costat de l&apos;altre en un marc de %3 × %4 px, i apilats els seus %5 vèrtexs es tocarien tots (com a màxim %6 poden començar apilats): reduïu els cossos, els costats o el radi, o eixampleu el marc.</translation>
        </message>
        <message>
            <source>The stable solver takes substeps from %1 to %2, an edge compliance from 0 to %3 and a damping ratio from 0 to %4.</source>
            <translation>El mètode estable admet de %1 a %2 subpassos, una flexibilitat de les arestes de 0 a %3 i una raó d&apos;esmorteïment de 0 a %4.</translation>
        </message>
        <message>
            <source>There are too few points.</source>
            <translation>Hi ha massa pocs punts.</translation>
        </message>
        <message>
            <source>A value is outside the range Granota accepts.</source>
            <translation>Un valor és fora de l&apos;interval que accepta Granota.</translation>
        </message>
        <message>
            <source>The path is not a file.</source>
            <translation>El camí no és un fitxer.</translation>
        </message>
        <message>
            <source>The text is cut off before its end.</source>
            <translation>El text s&apos;acaba abans d&apos;hora.</translation>
        </message>
        <message>
            <source>The system refused to read or write the file.</source>
            <translation>El sistema ha refusat llegir o escriure el fitxer.</translation>
        </message>
        <message>
            <source>A value is not written in a form Granota reads.</source>
            <translation>Un valor no està escrit en una forma que Granota llegeixi.</translation>
        </message>
        <message>
            <source>Line %1: %2</source>
            <translation>Línia %1: %2</translation>
        </message>
        <message>
            <source>The scene names a component %1 that does not exist (the components are %2).</source>
            <translation>L’escena anomena un component %1 que no existeix (els components són %2).</translation>
        </message>
        <message>
            <source>The degree of a B-spline must be from 1 to %2, not %1.</source>
            <translation>El grau d&apos;una B-spline ha de ser d&apos;1 a %2, no %1.</translation>
        </message>
        <message>
            <source>A B-spline of degree %1 needs at least %2 control points, not %3.</source>
            <translation>Una B-spline de grau %1 necessita almenys %2 punts de control, no %3.</translation>
        </message>
        <message>
            <source>A B-spline of degree %1 with %2 control points needs %3 knots, not %4.</source>
            <translation>Una B-spline de grau %1 amb %2 punts de control necessita %3 nusos, no %4.</translation>
        </message>
        <message>
            <source>A rational B-spline needs one weight per control point: %1 weights, not %2.</source>
            <translation>Una B-spline racional necessita un pes per punt de control: %1 pesos, no %2.</translation>
        </message>
        <message>
            <source>%1 is not a finite number.</source>
            <translation>%1 no és un nombre finit.</translation>
        </message>
        <message>
            <source>The knots must not decrease: u_%1 = %2 is greater than u_%3 = %4.</source>
            <translation>Els nusos no poden decréixer: u_%1 = %2 és més gran que u_%3 = %4.</translation>
        </message>
        <message>
            <source>The knot %1 is repeated %2 times; inside, a B-spline of degree %3 allows it at most %4 times.</source>
            <translation>El nus %1 es repeteix %2 vegades; a l&apos;interior, una B-spline de grau %3 el permet com a màxim %4 vegades.</translation>
        </message>
        <message>
            <source>The knot %1 is repeated %2 times; at an end, a B-spline of degree %3 allows it at most %4 times.</source>
            <translation>El nus %1 es repeteix %2 vegades; en un extrem, una B-spline de grau %3 el permet com a màxim %4 vegades.</translation>
        </message>
        <message>
            <source>The domain [%1, %2] of the B-spline is empty.</source>
            <translation>El domini [%1, %2] de la B-spline és buit.</translation>
        </message>
        <message>
            <source>The weight w_%1 = %2 must be positive.</source>
            <translation>El pes w_%1 = %2 ha de ser positiu.</translation>
        </message>
        <message>
            <source>A knot is inserted at least once, not %1 times.</source>
            <translation>Un nus s&apos;insereix almenys una vegada, no %1 vegades.</translation>
        </message>
        <message>
            <source>The knot %1 is outside the domain [%2, %3].</source>
            <translation>El nus %1 és fora del domini [%2, %3].</translation>
        </message>
        <message>
            <source>The knot %1 already has multiplicity %2: inserting it %3 more times would exceed the degree %4.</source>
            <translation>El nus %1 ja té multiplicitat %2: inserir-lo %3 vegades més superaria el grau %4.</translation>
        </message>
        <message>
            <source>This rational B-spline cannot float its ends: every choice of outer knots tried needs a weight that is not positive.</source>
            <translation>Aquesta B-spline racional no pot deixar lliures els extrems: cap de les eleccions de nusos exteriors provades evita un pes que no sigui positiu.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::ShortcutsDialog</name>
        <message>
            <source>Keyboard shortcuts</source>
            <translation>Dreceres de teclat</translation>
        </message>
        <message>
            <source>&amp;Close</source>
            <translation>&amp;Tanca</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::FieldInputFilter</name>
        <message>
            <source>%1 must be between %2 and %3.</source>
            <translation>%1 ha d’estar entre %2 i %3.</translation>
        </message>
        <message>
            <source>%1 was not applied.</source>
            <translation>No s’ha aplicat %1.</translation>
        </message>
        <message>
            <source>The value must be between %1 and %2.</source>
            <translation>El valor ha d’estar entre %1 i %2.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::BSplineTab</name>
        <message>
            <source>%1 knots for %2 points of degree %3 (n + p + 2 = %4 are needed)</source>
            <translation>%1 nusos per a %2 punts de grau %3 (en calen n + p + 2 = %4)</translation>
        </message>
        <message>
            <source>%1 weights for %2 points</source>
            <translation>%1 pesos per a %2 punts</translation>
        </message>
        <message numerus="yes">
            <source>%n weight(s) for %1 points: give one per point, or none.</source>
            <translation>
                <numerusform>%n pes per a %1 punts: doneu-ne un per punt, o cap.</numerusform>
                <numerusform>%n pesos per a %1 punts: doneu-ne un per punt, o cap.</numerusform>
            </translation>
        </message>
        <message>
            <source>&amp;Degree p:</source>
            <translation>&amp;Grau p:</translation>
        </message>
        <message>
            <source>&amp;Elevate degree</source>
            <translation>E&amp;leva el grau</translation>
        </message>
        <message>
            <source>&amp;Insert knot at u</source>
            <translation>&amp;Insereix un nus a u</translation>
        </message>
        <message>
            <source>&amp;Knots:</source>
            <translation>&amp;Nusos:</translation>
        </message>
        <message>
            <source>&amp;Remove knot</source>
            <translation>&amp;Elimina el nus</translation>
        </message>
        <message>
            <source>&amp;Weights:</source>
            <translation>&amp;Pesos:</translation>
        </message>
        <message>
            <source>A B-spline here has at most %1 control points.</source>
            <translation>Aquí una B-spline té com a màxim %1 punts de control.</translation>
        </message>
        <message>
            <source>A B-spline needs between 2 and %1 control points; the file has %2.</source>
            <translation>Una B-spline necessita entre 2 i %1 punts de control; el fitxer en té %2.</translation>
        </message>
        <message>
            <source>A B-spline of degree %1 needs at least %2 control points; there are %3.</source>
            <translation>Una B-spline de grau %1 necessita almenys %2 punts de control; n&apos;hi ha %3.</translation>
        </message>
        <message>
            <source>A knot can be repeated at most p = %1 times inside the domain and p + 1 times at an end, and the domain [uₚ, uₙ₊₁] cannot be empty.</source>
            <translation>Un nus es pot repetir com a màxim p = %1 vegades dins del domini i p + 1 vegades en un extrem, i el domini [uₚ, uₙ₊₁] no pot ser buit.</translation>
        </message>
        <message>
            <source>A knot is inserted inside the domain [%1, %2].</source>
            <translation>Un nus s&apos;insereix dins del domini [%1, %2].</translation>
        </message>
        <message>
            <source>A point has no exact form (dragged freely): the net is shown in doubles.</source>
            <translation>Un punt no té forma exacta (s&apos;ha arrossegat lliurement): la xarxa es mostra en decimals.</translation>
        </message>
        <message>
            <source>A weight must be positive, not %1.</source>
            <translation>Un pes ha de ser positiu, no %1.</translation>
        </message>
        <message>
            <source>Actions</source>
            <translation>Accions</translation>
        </message>
        <message>
            <source>B-spline</source>
            <translation>B-spline</translation>
        </message>
        <message>
            <source>B-spline canvas</source>
            <translation>Llenç de la B-spline</translation>
        </message>
        <message numerus="yes">
            <source>B-spline of degree %1 with %n control point(s) and %2 knots.</source>
            <translation>
                <numerusform>B-spline de grau %1 amb %n punt de control i %2 nusos.</numerusform>
                <numerusform>B-spline de grau %1 amb %n punts de control i %2 nusos.</numerusform>
            </translation>
        </message>
        <message>
            <source>B-splines</source>
            <translation>B-splines</translation>
        </message>
        <message>
            <source>Basis functions Nᵢ,ₚ(u) (Cox–de Boor)</source>
            <translation>Funcions de base Nᵢ,ₚ(u) (Cox–de Boor)</translation>
        </message>
        <message>
            <source>Basis functions at u (degree p = %1)</source>
            <translation>Funcions de base a u (grau p = %1)</translation>
        </message>
        <message>
            <source>Boehm&apos;s knot insertion: one more point and one more knot, the curve unchanged; the old polygon stays drawn dashed under the new one.</source>
            <translation>Inserció de nusos de Boehm: un punt i un nus més, i la corba no canvia; el polígon antic queda dibuixat discontinu sota el nou.</translation>
        </message>
        <message>
            <source>Bé&amp;zier segments</source>
            <translation>Segments de Bé&amp;zier</translation>
        </message>
        <message>
            <source>Bézier (no interior knot)</source>
            <translation>Bézier (sense nusos interiors)</translation>
        </message>
        <message>
            <source>C&amp;ubic Bézier circle beside</source>
            <translation>Circumferència de Bézier c&amp;úbica al costat</translation>
        </message>
        <message>
            <source>Change the weights</source>
            <translation>Canvia els pesos</translation>
        </message>
        <message>
            <source>Clamped: p + 1 equal knots at each end, the curve starts at P₀ and ends at Pₙ. Uniform: 0, 1, 2, …, the ends float. Bézier: no interior knot, degree n, exactly the Bézier curve of the points (Def 2.4). “Edited” is shown once a knot was moved or inserted.</source>
            <translation>Subjectes: p + 1 nusos iguals a cada extrem; la corba comença a P₀ i acaba a Pₙ. Uniformes: 0, 1, 2, …; els extrems queden lliures. Bézier: sense nusos interiors, grau n, exactament la corba de Bézier dels punts (Def. 2.4). «Editats» es mostra quan s&apos;ha mogut o inserit un nus.</translation>
        </message>
        <message>
            <source>Conic: a hyperbola (w = 2)</source>
            <translation>Cònica: una hipèrbola (w = 2)</translation>
        </message>
        <message>
            <source>Conic: a parabola (w = 1)</source>
            <translation>Cònica: una paràbola (w = 1)</translation>
        </message>
        <message>
            <source>Conic: an ellipse (w = 1/2)</source>
            <translation>Cònica: una el·lipse (w = 1/2)</translation>
        </message>
        <message>
            <source>Dashed red: the cubic Bézier quarter circle (1, 0), (1, k), (k, 1), (0, 1), k = 4(√2 − 1)/3 ≈ %1: its radius is off by up to %2; the rational quarter circle&apos;s by nothing (x² + y² = 1 exactly at every rational u).</source>
            <translation>En vermell discontinu: el quart de circumferència de Bézier cúbic (1, 0), (1, k), (k, 1), (0, 1), k = 4(√2 − 1)/3 ≈ %1: el seu radi s&apos;allunya fins a %2; el del quart de circumferència racional, gens (x² + y² = 1 exactament a cada u racional).</translation>
        </message>
        <message>
            <source>Degree %1</source>
            <translation>Grau %1</translation>
        </message>
        <message>
            <source>Degree p + 1, the same curve: more points, each knot once more.</source>
            <translation>Grau p + 1, la mateixa corba: més punts, cada nus una vegada més.</translation>
        </message>
        <message>
            <source>Drag a point to move it; double-click to add one; Delete removes the selected point; drag the paper to pan, wheel to zoom. The ringed points are the p + 1 that act at u.</source>
            <translation>Arrossegueu un punt per moure&apos;l; feu doble clic per afegir-ne un; Supr elimina el punt seleccionat; arrossegueu el paper per desplaçar-lo i feu servir la roda per fer zoom. Els punts encerclats són els p + 1 que actuen a u.</translation>
        </message>
        <message>
            <source>Drag a point; drag a knot on the ruler, double-click it to insert one; move u to follow de Boor&apos;s construction.</source>
            <translation>Arrossegueu punts i nusos; doble clic al regle: un nus més; moveu u per seguir De Boor.</translation>
        </message>
        <message>
            <source>Draw the control polygon of each Bézier segment of the curve (the knots inserted up to multiplicity p): one polynomial piece per span.</source>
            <translation>Dibuixa el polígon de control de cada segment de Bézier de la corba (els nusos inserits fins a multiplicitat p): un tros polinòmic per interval.</translation>
        </message>
        <message>
            <source>Each Nᵢ,ₚ in the colour of Pᵢ&apos;s ring; the shaded band is the domain [uₚ, uₙ₊₁], the vertical line is u.</source>
            <translation>Cada Nᵢ,ₚ del color de l&apos;anella de Pᵢ; la franja ombrejada és el domini [uₚ, uₙ₊₁] i la línia vertical és u.</translation>
        </message>
        <message>
            <source>Elevate the degree to %1</source>
            <translation>Eleva el grau a %1</translation>
        </message>
        <message>
            <source>Ex 2.2 as a B-spline (no interior knot)</source>
            <translation>L&apos;Ex. 2.2 sense nusos interiors</translation>
        </message>
        <message>
            <source>Ex 2.2&apos;s Bézier curve as a B-spline; a uniform cubic closed on Ex 2.13&apos;s points; the circle and the conics, exactly, as rational curves.</source>
            <translation>La corba de Bézier de l&apos;Ex. 2.2 com a B-spline; una cúbica uniforme tancada sobre els punts de l&apos;Ex. 2.13; la circumferència i les còniques, exactes, com a corbes racionals.</translation>
        </message>
        <message>
            <source>Exact results</source>
            <translation>Resultats exactes</translation>
        </message>
        <message>
            <source>Exact results and points</source>
            <translation>Resultats exactes i punts</translation>
        </message>
        <message>
            <source>Exact results: de Boor&apos;s net at u, the basis functions there, their supports, the knots with their multiplicities and the continuity of the curve at each.</source>
            <translation>Resultats exactes: la xarxa de De Boor a u, les funcions de base en aquest punt, els seus suports, els nusos amb les seves multiplicitats i la continuïtat de la corba a cadascun.</translation>
        </message>
        <message>
            <source>Examples</source>
            <translation>Exemples</translation>
        </message>
        <message>
            <source>Examples…</source>
            <translation>Exemples…</translation>
        </message>
        <message>
            <source>Hide de Boor&apos;s net</source>
            <translation>Amaga la xarxa de De Boor</translation>
        </message>
        <message>
            <source>Hide the Bézier segments</source>
            <translation>Amaga els segments de Bézier</translation>
        </message>
        <message>
            <source>Hide the cubic circle</source>
            <translation>Amaga la circumferència cúbica</translation>
        </message>
        <message>
            <source>Insert knot %1</source>
            <translation>Insereix el nus %1</translation>
        </message>
        <message>
            <source>Knot %1 inserted: %2 control points now, the same curve.</source>
            <translation>Nus %1 inserit: ara hi ha %2 punts de control, i la corba és la mateixa.</translation>
        </message>
        <message>
            <source>Knot %1 removed: the curve is exactly the same.</source>
            <translation>Nus %1 eliminat: la corba és exactament la mateixa.</translation>
        </message>
        <message>
            <source>Knot ruler</source>
            <translation>Regle de nusos</translation>
        </message>
        <message>
            <source>Knots</source>
            <translation>Nusos</translation>
        </message>
        <message>
            <source>Knots: %1</source>
            <translation>Nusos: %1</translation>
        </message>
        <message>
            <source>Load %1</source>
            <translation>Carrega %1</translation>
        </message>
        <message>
            <source>Load Ex %1</source>
            <translation>Carrega l&apos;Ex. %1</translation>
        </message>
        <message>
            <source>Move knot u%1</source>
            <translation>Mou el nus u%1</translation>
        </message>
        <message>
            <source>Move u</source>
            <translation>Mou u</translation>
        </message>
        <message>
            <source>Move u along the domain again and again; Pause makes it one undo step.</source>
            <translation>Mou u al llarg del domini una vegada i una altra; en fer Pausa, queda en un sol pas per desfer.</translation>
        </message>
        <message>
            <source>No weights</source>
            <translation>Sense pesos</translation>
        </message>
        <message>
            <source>One weight wᵢ &gt; 0 per point, separated by commas (1, 1, 2): a rational B-spline (NURBS), c(u) = Σ wᵢNᵢ,ₚPᵢ / Σ wᵢNᵢ,ₚ. Empty: polynomial.</source>
            <translation>Un pes wᵢ &gt; 0 per punt, separats per comes (1, 1, 2): una B-spline racional (NURBS), c(u) = Σ wᵢNᵢ,ₚPᵢ / Σ wᵢNᵢ,ₚ. Buit: polinòmica.</translation>
        </message>
        <message>
            <source>Only a knot inside the domain can be removed; %1 is at its end or outside it.</source>
            <translation>Només es pot eliminar un nus de dins del domini; %1 és en un extrem o fora.</translation>
        </message>
        <message>
            <source>Parameter u</source>
            <translation>Paràmetre u</translation>
        </message>
        <message>
            <source>Pause</source>
            <translation>Pausa</translation>
        </message>
        <message>
            <source>Play</source>
            <translation>Reprodueix</translation>
        </message>
        <message>
            <source>Play u</source>
            <translation>Reprodueix u</translation>
        </message>
        <message>
            <source>Point %1 of the B-spline tab is not a finite number.</source>
            <translation>El punt %1 de la pestanya B-splines no és un nombre finit.</translation>
        </message>
        <message>
            <source>Point %1 of the B-spline tab is not a pair of numbers.</source>
            <translation>El punt %1 de la pestanya B-splines no és un parell de nombres.</translation>
        </message>
        <message>
            <source>Points</source>
            <translation>Punts</translation>
        </message>
        <message>
            <source>Quarter circle: exact and cubic</source>
            <translation>Quart de circumferència: exacte i cúbic</translation>
        </message>
        <message>
            <source>Remove knot %1</source>
            <translation>Elimina el nus %1</translation>
        </message>
        <message>
            <source>Remove the knot selected on the ruler, only if the curve stays exactly the same.</source>
            <translation>Elimina el nus seleccionat al regle, només si la corba queda exactament igual.</translation>
        </message>
        <message>
            <source>Removing a knot would leave fewer than p + 1 = %1 points.</source>
            <translation>Eliminar un nus deixaria menys de p + 1 = %1 punts.</translation>
        </message>
        <message>
            <source>Ruler keys: Left/Right select a knot, Shift+Left/Right move it, Insert inserts a knot at u, Delete removes the selected knot; Tab leaves the ruler.</source>
            <translation>Tecles del regle: Esquerra/Dreta seleccionen un nus, Maj+Esquerra/Dreta el mouen, Insert insereix un nus a u, Supr elimina el nus seleccionat; Tab surt del regle.</translation>
        </message>
        <message>
            <source>Select a knot on the ruler first (click it, or Left/Right while the ruler has the focus).</source>
            <translation>Primer seleccioneu un nus al regle (feu-hi clic, o premeu Esquerra/Dreta mentre el regle té el focus).</translation>
        </message>
        <message>
            <source>Show de Boor&apos;s net</source>
            <translation>Mostra la xarxa de De Boor</translation>
        </message>
        <message>
            <source>Show the Bézier segments</source>
            <translation>Mostra els segments de Bézier</translation>
        </message>
        <message>
            <source>Show the cubic circle</source>
            <translation>Mostra la circumferència cúbica</translation>
        </message>
        <message>
            <source>Span k = %1: u&lt;sub&gt;%1&lt;/sub&gt; ≤ u &amp;lt; u&lt;sub&gt;%2&lt;/sub&gt;. Only P&lt;sub&gt;%3&lt;/sub&gt;…P&lt;sub&gt;%1&lt;/sub&gt; act here (local support); level r interpolates level r − 1 with α = (u − u&lt;sub&gt;j&lt;/sub&gt;)/(u&lt;sub&gt;j+p+1−r&lt;/sub&gt; − u&lt;sub&gt;j&lt;/sub&gt;).</source>
            <translation>Interval k = %1: u&lt;sub&gt;%1&lt;/sub&gt; ≤ u &amp;lt; u&lt;sub&gt;%2&lt;/sub&gt;. Només P&lt;sub&gt;%3&lt;/sub&gt;…P&lt;sub&gt;%1&lt;/sub&gt; hi actuen (suport local); el nivell r interpola el nivell r − 1 amb α = (u − u&lt;sub&gt;j&lt;/sub&gt;)/(u&lt;sub&gt;j+p+1−r&lt;/sub&gt; − u&lt;sub&gt;j&lt;/sub&gt;).</translation>
        </message>
        <message>
            <source>Supports [uᵢ, uᵢ₊ₚ₊₁)</source>
            <translation>Suports [uᵢ, uᵢ₊ₚ₊₁)</translation>
        </message>
        <message>
            <source>The B-spline in the document is not valid: %1.</source>
            <translation>La B-spline del document no és vàlida: %1.</translation>
        </message>
        <message>
            <source>The B-spline settings are not valid (“%1”).</source>
            <translation>La configuració de la B-spline no és vàlida («%1»).</translation>
        </message>
        <message>
            <source>The B-spline&apos;s control points are missing or not a list.</source>
            <translation>Falten els punts de control de la B-spline o no són una llista.</translation>
        </message>
        <message>
            <source>The Bézier preset has degree n = number of points − 1, at most %1: remove points first.</source>
            <translation>Els nusos de Bézier donen grau n = nombre de punts − 1, com a màxim %1: primer elimineu punts.</translation>
        </message>
        <message>
            <source>The circle, exactly (NURBS)</source>
            <translation>La circumferència, exacta (NURBS)</translation>
        </message>
        <message>
            <source>The control points P0…Pn as numbers; fractions such as 1/3 are accepted.</source>
            <translation>Els punts de control P0…Pn com a nombres; s&apos;accepten fraccions com ara 1/3.</translation>
        </message>
        <message>
            <source>The curve needs the knot %1: removing it would change the curve.</source>
            <translation>La corba necessita el nus %1: eliminar-lo canviaria la corba.</translation>
        </message>
        <message>
            <source>The degree is at most %1.</source>
            <translation>El grau és com a màxim %1.</translation>
        </message>
        <message>
            <source>The degree of every piece, 1 to 10: the curve is Cᵖ⁻¹ at a simple knot. Needs at least p + 1 points; the knots go back to the preset.</source>
            <translation>El grau de cada tros, d&apos;1 a 10: la corba és Cᵖ⁻¹ en un nus simple. Calen almenys p + 1 punts; els nusos tornen als predefinits.</translation>
        </message>
        <message>
            <source>The knots u₀ ≤ … ≤ uₙ₊ₚ₊₁: drag one (it never passes its neighbours), double-click to insert one, the badge is a knot&apos;s multiplicity. Bold: the domain [uₚ, uₙ₊₁]; yellow: the span that holds u.</source>
            <translation>Els nusos u₀ ≤ … ≤ uₙ₊ₚ₊₁: arrossegueu-ne un (mai no passa els veïns) o feu doble clic per inserir-ne un; la insígnia és la multiplicitat d&apos;un nus. En negreta: el domini [uₚ, uₙ₊₁]; en groc: l&apos;interval que conté u.</translation>
        </message>
        <message>
            <source>The usual cubic Bézier quarter circle (1, 0), (1, k), (k, 1), (0, 1), k = 4(√2 − 1)/3, dashed: close to the circle but not on it (its radial error is in the exact panel); the rational quarter circle is exact.</source>
            <translation>El quart de circumferència de Bézier cúbic habitual (1, 0), (1, k), (k, 1), (0, 1), k = 4(√2 − 1)/3, discontinu: a prop de la circumferència però no a sobre (l&apos;error radial és al tauler exacte); el quart de circumferència racional és exacte.</translation>
        </message>
        <message>
            <source>This B-spline cannot be drawn: %1</source>
            <translation>Aquesta B-spline no es pot dibuixar: %1</translation>
        </message>
        <message>
            <source>Closed uniform cubic (Ex 2.13)</source>
            <translation>Cúbica uniforme tancada (Ex. 2.13)</translation>
        </message>
        <message>
            <source>Weights are numbers separated by commas, such as 1, 1, 2 or 1, 1/2, 1; empty for none.</source>
            <translation>Els pesos són nombres separats per comes, com ara 1, 1, 2 o 1, 1/2, 1; buit per a cap.</translation>
        </message>
        <message>
            <source>Weights: %1</source>
            <translation>Pesos: %1</translation>
        </message>
        <message>
            <source>broken</source>
            <translation>trencada</translation>
        </message>
        <message>
            <source>c(u) = Σ Nᵢ,ₚ(u) Pᵢ: the weight of each control point along the curve. Nᵢ,ₚ is zero outside [uᵢ, uᵢ₊ₚ₊₁) (local support), the functions add up to 1 on the domain (the dashed line), and at a knot of multiplicity m they are Cᵖ⁻ᵐ.</source>
            <translation>c(u) = Σ Nᵢ,ₚ(u) Pᵢ: el pes de cada punt de control al llarg de la corba. Nᵢ,ₚ és zero fora de [uᵢ, uᵢ₊ₚ₊₁) (suport local), les funcions sumen 1 al domini (la línia discontínua) i en un nus de multiplicitat m són Cᵖ⁻ᵐ.</translation>
        </message>
        <message>
            <source>clamped (open uniform)</source>
            <translation>subjectes (uniformes oberts)</translation>
        </message>
        <message>
            <source>continuity C&lt;sup&gt;p−m&lt;/sup&gt;</source>
            <translation>continuïtat C&lt;sup&gt;p−m&lt;/sup&gt;</translation>
        </message>
        <message>
            <source>de Boor&apos;s &amp;net at u</source>
            <translation>&amp;Xarxa de De Boor a u</translation>
        </message>
        <message>
            <source>de Boor&apos;s algorithm at u = %1</source>
            <translation>Algorisme de De Boor a u = %1</translation>
        </message>
        <message>
            <source>de Boor&apos;s algorithm at u step by step: level r interpolates level r − 1, one colour per level as in the De Casteljau tab, from the span&apos;s p + 1 points down to c(u).</source>
            <translation>L&apos;algorisme de De Boor a u pas a pas: el nivell r interpola el nivell r − 1, un color per nivell com a la pestanya De Casteljau, des dels p + 1 punts de l&apos;interval fins a c(u).</translation>
        </message>
        <message>
            <source>degree %1 needs at least %2 points</source>
            <translation>el grau %1 necessita almenys %2 punts</translation>
        </message>
        <message>
            <source>edited</source>
            <translation>editats</translation>
        </message>
        <message>
            <source>knot</source>
            <translation>nus</translation>
        </message>
        <message>
            <source>level r</source>
            <translation>nivell r</translation>
        </message>
        <message>
            <source>multiplicity m</source>
            <translation>multiplicitat m</translation>
        </message>
        <message>
            <source>non-zero on</source>
            <translation>no nul·la a</translation>
        </message>
        <message>
            <source>none (polynomial)</source>
            <translation>cap (polinòmica)</translation>
        </message>
        <message>
            <source>outside or at an end</source>
            <translation>fora o en un extrem</translation>
        </message>
        <message>
            <source>points P&lt;sub&gt;j&lt;/sub&gt;&lt;sup&gt;r&lt;/sup&gt;</source>
            <translation>punts P&lt;sub&gt;j&lt;/sub&gt;&lt;sup&gt;r&lt;/sup&gt;</translation>
        </message>
        <message>
            <source>u = %1 is a knot of multiplicity %2 already: once more would break the curve (at most p = %3 times).</source>
            <translation>u = %1 ja és un nus de multiplicitat %2: una vegada més trencaria la corba (com a màxim p = %3 vegades).</translation>
        </message>
        <message>
            <source>u in the domain [uₚ, uₙ₊₁]: the point c(u) and de Boor&apos;s net there.</source>
            <translation>u al domini [uₚ, uₙ₊₁]: el punt c(u) i la xarxa de De Boor en aquest punt.</translation>
        </message>
        <message>
            <source>uniform</source>
            <translation>uniformes</translation>
        </message>
        <message>
            <source>value</source>
            <translation>valor</translation>
        </message>
        <message>
            <source>Σ N&lt;sub&gt;i,p&lt;/sub&gt;(u) = %1: partition of unity</source>
            <translation>Σ N&lt;sub&gt;i,p&lt;/sub&gt;(u) = %1: partició de la unitat</translation>
        </message>
        <message>
            <source>An inset with the curve as the projection of a polynomial B-spline in space: the points Hᵢ = (wᵢxᵢ, wᵢyᵢ, wᵢ) (purple), the polynomial curve through them, and the rays from the origin O through each Hᵢ down to the plane w = 1, where they meet Pᵢ and the rational curve.</source>
            <translation>Un requadre amb la corba com a projecció d&apos;una B-spline polinòmica de l&apos;espai: els punts Hᵢ = (wᵢxᵢ, wᵢyᵢ, wᵢ) (en lila), la corba polinòmica que determinen i els raigs des de l&apos;origen O per cada Hᵢ fins al pla w = 1, on troben Pᵢ i la corba racional.</translation>
        </message>
        <message>
            <source>Change the weight of P%1</source>
            <translation>Canvia el pes de P%1</translation>
        </message>
        <message>
            <source>Curvature κ against arc length s</source>
            <translation>Curvatura κ segons la longitud d&apos;arc s</translation>
        </message>
        <message>
            <source>Curvature κ(s) in the &amp;plot</source>
            <translation>&amp;Curvatura κ(s) al gràfic</translation>
        </message>
        <message>
            <source>Drag a point to move it; double-click to add one; Delete removes the selected point; drag the paper to pan, wheel to zoom; Shift+wheel over a point changes its weight. The ringed points are the p + 1 that act at u.</source>
            <translation>Arrossegueu un punt per moure&apos;l; feu doble clic per afegir-ne un; Supr elimina el punt seleccionat; arrossegueu el paper per desplaçar-lo i feu servir la roda per fer zoom; Maj+roda sobre un punt en canvia el pes. Els punts encerclats són els p + 1 que actuen a u.</translation>
        </message>
        <message>
            <source>Hide the homogeneous curve</source>
            <translation>Amaga la corba homogènia</translation>
        </message>
        <message>
            <source>Homo&amp;geneous curve (wx, wy, w)</source>
            <translation>Corba &amp;homogènia (wx, wy, w)</translation>
        </message>
        <message>
            <source>Plot the basis functions</source>
            <translation>Mostra les funcions de base</translation>
        </message>
        <message>
            <source>Plot the curvature</source>
            <translation>Mostra la curvatura</translation>
        </message>
        <message>
            <source>Plot the signed curvature κ of the curve against its arc length s instead of the basis functions, each interior knot labelled with the continuity Cᵖ⁻ᵐ there: κ may jump at a knot of multiplicity p − 1 (C¹) and the curve may turn a corner at one of multiplicity p (C⁰).</source>
            <translation>Mostra la curvatura amb signe κ de la corba segons la longitud d&apos;arc s en lloc de les funcions de base, amb cada nus interior marcat amb la continuïtat Cᵖ⁻ᵐ que hi té: κ pot saltar en un nus de multiplicitat p − 1 (C¹) i la corba pot fer una punta en un de multiplicitat p (C⁰).</translation>
        </message>
        <message>
            <source>Show the homogeneous curve</source>
            <translation>Mostra la corba homogènia</translation>
        </message>
        <message>
            <source>The curve in (wx, wy, w)</source>
            <translation>La corba a (wx, wy, w)</translation>
        </message>
        <message>
            <source>The weight of P%1 is already %2, the largest the canvas reaches.</source>
            <translation>El pes de P%1 ja és %2, el més gran que permet el llenç.</translation>
        </message>
        <message>
            <source>The weight of P%1 is already %2, the smallest the canvas reaches.</source>
            <translation>El pes de P%1 ja és %2, el més petit que permet el llenç.</translation>
        </message>
        <message>
            <source>arc length s</source>
            <translation>longitud d&apos;arc s</translation>
        </message>
        <message>
            <source>curvature κ</source>
            <translation>curvatura κ</translation>
        </message>
        <message>
            <source>κ = (x′y″ − y′x″)/|c′|³, positive where the curve turns left, computed on each Bézier piece of the curve. At a knot of multiplicity m the curve is Cᵖ⁻ᵐ: κ is continuous where the curve is C², it may jump at C¹ (a break in the line), and at C⁰ the curve may turn a corner.</source>
            <translation>κ = (x′y″ − y′x″)/|c′|³, positiva on la corba gira a l&apos;esquerra, calculada sobre cada tram de Bézier de la corba. En un nus de multiplicitat m la corba és Cᵖ⁻ᵐ: κ és contínua on la corba és C², pot saltar on és C¹ (un tall a la línia) i on és C⁰ la corba pot fer una punta.</translation>
        </message>
        <message>
            <source>κ(s) of the curve; the light vertical lines are its interior knots, each labelled with the continuity there.</source>
            <translation>κ(s) de la corba; les línies verticals clares són els nusos interiors, cadascun amb la continuïtat que hi té.</translation>
        </message>
        <message>
            <source>Keys: ] and [ pick a point, arrows nudge it (Shift: ×10), + and − change its weight, Delete removes it; Tab leaves the canvas.</source>
            <translation>Tecles: ] i [ trien un punt, les fletxes el mouen (Maj: ×10), + i − en canvien el pes, Supr l&apos;elimina; Tab surt del llenç.</translation>
        </message>
        <message>
            <source>The weight wᵢ of each point (a rational B-spline when not all are 1)</source>
            <translation>El pes wᵢ de cada punt (una B-spline racional quan no tots valen 1)</translation>
        </message>
        <message>
            <source>“%1” is not a weight: type a decimal (0.7) or a fraction (3/2) greater than 0.</source>
            <translation>«%1» no és un pes: escriviu un decimal (0,7) o una fracció (3/2) més gran que 0.</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::ConventionsTable</name>
        <message>
            <source>From τ</source>
            <translation>A partir de τ</translation>
        </message>
        <message>
            <source>Granota, the thesis (Def 2.8)</source>
            <translation>Granota, la tesi (Def. 2.8)</translation>
        </message>
        <message>
            <source>Kochanek–Bartels (C = B = 0)</source>
            <translation>Kochanek–Bartels (C = B = 0)</translation>
        </message>
        <message>
            <source>Parameter</source>
            <translation>Paràmetre</translation>
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
            <translation>Font</translation>
        </message>
        <message>
            <source>Tension conventions</source>
            <translation>Convencions de la tensió</translation>
        </message>
        <message>
            <source>The same Catmull-Rom tangent τ(qᵢ₊₁ − qᵢ₋₁) in each source&apos;s convention, with its value for the curve shown: the selected τ, the cardinal c, or T of the selected point.</source>
            <translation>La mateixa tangent de Catmull-Rom τ(qᵢ₊₁ − qᵢ₋₁) en la convenció de cada font, amb el seu valor per a la corba dibuixada: la τ seleccionada, la c cardinal o la T del punt seleccionat.</translation>
        </message>
        <message>
            <source>Value</source>
            <translation>Valor</translation>
        </message>
        <message>
            <source>d3-shape</source>
            <translation>d3-shape</translation>
        </message>
        <message>
            <source>none (τ ≤ 0)</source>
            <translation>cap (τ ≤ 0)</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::CurveFamilyNames</name>
        <message>
            <source>Cardinal (one tension c)</source>
            <translation>Cardinal (una tensió c)</translation>
        </message>
        <message>
            <source>Catmull-Rom (Def 2.10)</source>
            <translation>Catmull-Rom (Def. 2.10)</translation>
        </message>
        <message>
            <source>C² spline in the plane (Def 2.1)</source>
            <translation>Spline C² al pla (Def. 2.1)</translation>
        </message>
        <message>
            <source>Function data y(x) (Def 2.3)</source>
            <translation>Dades y(x) d&apos;una funció (Def. 2.3)</translation>
        </message>
        <message>
            <source>Hermite (drag the tangents)</source>
            <translation>Hermite (tangents lliures)</translation>
        </message>
        <message>
            <source>Kochanek–Bartels: T, C, B per point</source>
            <translation>Kochanek–Bartels: TCB per punt</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::FamilyPanel</name>
        <message>
            <source>All points</source>
            <translation>Tots els punts</translation>
        </message>
        <message>
            <source>Back to the Catmull-Rom tangents</source>
            <translation>Torna a les tangents de Catmull-Rom</translation>
        </message>
        <message>
            <source>Bias B = %1:</source>
            <translation>Biaix B = %1:</translation>
        </message>
        <message>
            <source>Bias B in steps of 1/20: &gt; 0 leans the tangents towards the incoming chord, &lt; 0 towards the outgoing one.</source>
            <translation>Biaix B en passos d&apos;1/20: &gt; 0 inclina les tangents cap a la corda d&apos;entrada, &lt; 0 cap a la de sortida.</translation>
        </message>
        <message>
            <source>Continuity C = %1:</source>
            <translation>Continuïtat C = %1:</translation>
        </message>
        <message>
            <source>Continuity C in steps of 1/20: 0 keeps the curve C¹ (Prop 2.3); any other value makes the two tangents differ; −1 gives corners.</source>
            <translation>Continuïtat C en passos d&apos;1/20: 0 manté la corba C¹ (Prop. 2.3); qualsevol altre valor fa que les dues tangents siguin diferents; −1 fa cantonades.</translation>
        </message>
        <message>
            <source>Def 2.8 builds each segment from two points and two tangents. Catmull-Rom sets the tangents by the rule τ(qᵢ₊₁ − qᵢ₋₁); cardinal and Kochanek–Bartels by other rules; Hermite lets you drag them; the C² splines solve for them.</source>
            <translation>La Def. 2.8 construeix cada segment a partir de dos punts i dues tangents. Catmull-Rom fixa les tangents amb la regla τ(qᵢ₊₁ − qᵢ₋₁); la cardinal i la de Kochanek–Bartels, amb altres regles; Hermite us les deixa arrossegar; els splines C² les obtenen resolent un sistema.</translation>
        </message>
        <message>
            <source>Every tangent as the Catmull-Rom rule τ(qᵢ₊₁ − qᵢ₋₁) of the selected τ sets it.</source>
            <translation>Cada tangent com la fixa la regla de Catmull-Rom τ(qᵢ₊₁ − qᵢ₋₁) de la τ seleccionada.</translation>
        </message>
        <message>
            <source>Every tangent is yours: drag the square at its end, or Alt + arrows for the selected point&apos;s.</source>
            <translation>Cada tangent és vostra: arrossegueu el quadrat del seu extrem, o Alt + fletxes per a la del punt seleccionat.</translation>
        </message>
        <message>
            <source>Famil&amp;y:</source>
            <translation>Famí&amp;lia:</translation>
        </message>
        <message>
            <source>Family: how the tangents are chosen</source>
            <translation>Família: com es trien les tangents</translation>
        </message>
        <message>
            <source>Move T, C, B of every point at once (also when no point is selected).</source>
            <translation>Mou T, C, B de tots els punts alhora (també si no n&apos;hi ha cap de seleccionat).</translation>
        </message>
        <message>
            <source>T, C, B of every point:</source>
            <translation>T, C, B de tots els punts:</translation>
        </message>
        <message>
            <source>T, C, B of the selected point q%1:</source>
            <translation>T, C, B del punt seleccionat q%1:</translation>
        </message>
        <message>
            <source>Tangents set by a rule: (1 − c)(qᵢ₊₁ − qᵢ₋₁)/2, Catmull-Rom with τ = (1 − c)/2.</source>
            <translation>Tangents fixades per una regla: (1 − c)(qᵢ₊₁ − qᵢ₋₁)/2, Catmull-Rom amb τ = (1 − c)/2.</translation>
        </message>
        <message>
            <source>Tangents set by a rule: T scales them, C ≠ 0 makes the incoming and outgoing tangents differ (a corner), B leans them towards one chord.</source>
            <translation>Tangents fixades per una regla: T les escala, C ≠ 0 fa que la tangent d&apos;entrada i la de sortida siguin diferents (una cantonada), B les inclina cap a una de les cordes.</translation>
        </message>
        <message>
            <source>Tension T = %1:</source>
            <translation>Tensió T = %1:</translation>
        </message>
        <message>
            <source>Tension T in steps of 1/20: τ = (1 − T)/2; 1 gives zero tangents.</source>
            <translation>Tensió T en passos d&apos;1/20: τ = (1 − T)/2; 1 dona tangents nul·les.</translation>
        </message>
        <message>
            <source>The cardinal tension c in steps of 1/20 from −1 to 1: c = 0 is Catmull-Rom&apos;s τ = 1/2, c = 1 gives zero tangents (straight segments).</source>
            <translation>La tensió cardinal c en passos d&apos;1/20 de −1 a 1: c = 0 és la τ = 1/2 de Catmull-Rom, c = 1 dona tangents nul·les (segments rectes).</translation>
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
            <translation>Continuïtat als nusos</translation>
        </message>
        <message>
            <source>Each knot of the curve drawn: ✓ where the derivatives of order 0, 1, 2 agree (C⁰, C¹, C²) and where the direction (G¹) and the curvature (G²) agree; the last column is the jump of the tangent. Catmull-Rom curves are C¹ at every knot (Prop 2.3); a continuity C ≠ 0 breaks it.</source>
            <translation>Cada nus de la corba dibuixada: ✓ on coincideixen les derivades d&apos;ordre 0, 1, 2 (C⁰, C¹, C²) i on coincideixen la direcció (G¹) i la curvatura (G²); l&apos;última columna és el salt de la tangent. Les corbes de Catmull-Rom són C¹ a tots els nusos (Prop. 2.3); una continuïtat C ≠ 0 ho trenca.</translation>
        </message>
        <message>
            <source>Knot</source>
            <translation>Nus</translation>
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
            <translation>Un punt no és un nombre finit.</translation>
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
            <translation>Les dades d&apos;una funció necessiten almenys 2 punts.</translation>
        </message>
        <message>
            <source>Steffen</source>
            <translation>Steffen</translation>
        </message>
        <message>
            <source>The curve overflows: the coordinates are too large.</source>
            <translation>La corba desborda: les coordenades són massa grans.</translation>
        </message>
        <message>
            <source>The points are not data y(x): their abscissae must increase strictly from q0 to qn. Move a point, or choose another family: the points are kept.</source>
            <translation>Els punts no són dades y(x): les abscisses han de créixer estrictament de q0 a qn. Moveu un punt o trieu una altra família: els punts es conserven.</translation>
        </message>
        <message>
            <source>natural spline</source>
            <translation>spline natural</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::FunctionDataPanel</name>
        <message>
            <source>Curve</source>
            <translation>Corba</translation>
        </message>
        <message>
            <source>Curves on the data</source>
            <translation>Corbes sobre les dades</translation>
        </message>
        <message>
            <source>Interval</source>
            <translation>Interval</translation>
        </message>
        <message>
            <source>Largest overshoot beyond the neighbouring data values:</source>
            <translation>Com més sobresurt cada corba dels valors veïns:</translation>
        </message>
        <message>
            <source>Largest overshoot of each curve</source>
            <translation>El màxim que sobresurt cada corba</translation>
        </message>
        <message>
            <source>On each interval [xᵢ, xᵢ₊₁], fill the part of a curve outside the band between yᵢ and yᵢ₊₁: where it goes beyond its neighbouring data values.</source>
            <translation>A cada interval [xᵢ, xᵢ₊₁], omple la part d&apos;una corba fora de la franja entre yᵢ i yᵢ₊₁: on va més enllà dels valors veïns.</translation>
        </message>
        <message>
            <source>Overshoot</source>
            <translation>Sobresurt</translation>
        </message>
        <message>
            <source>Overshoot shading</source>
            <translation>Ombrejat del que sobresurt</translation>
        </message>
        <message>
            <source>Shade the o&amp;vershoot</source>
            <translation>Ombreja el &amp;que sobresurt</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::PlaneSplineCurves</name>
        <message>
            <source>A closed C² spline needs at least 3 points.</source>
            <translation>Un spline C² tancat necessita almenys 3 punts.</translation>
        </message>
        <message>
            <source>A point or an end tangent is not a finite number.</source>
            <translation>Un punt o una tangent d&apos;extrem no és un nombre finit.</translation>
        </message>
        <message>
            <source>An open C² spline needs at least 2 points.</source>
            <translation>Un spline C² obert necessita almenys 2 punts.</translation>
        </message>
        <message>
            <source>C² spline</source>
            <translation>spline C²</translation>
        </message>
        <message>
            <source>C² spline, %1</source>
            <translation>Spline C², %1</translation>
        </message>
        <message>
            <source>Points q%1 and q%2 coincide: %3 parameters need distinct consecutive points (use uniform parameters, or move one).</source>
            <translation>Els punts q%1 i q%2 coincideixen: els paràmetres de %3 necessiten punts consecutius diferents (useu paràmetres uniformes o moveu-ne un).</translation>
        </message>
        <message>
            <source>The spline overflows: the coordinates are too large.</source>
            <translation>L&apos;spline desborda: les coordenades són massa grans.</translation>
        </message>
        <message>
            <source>centripetal</source>
            <translation>centrípeta</translation>
        </message>
        <message>
            <source>chord length</source>
            <translation>longitud de corda</translation>
        </message>
        <message>
            <source>clamped</source>
            <translation>subjectes</translation>
        </message>
        <message>
            <source>dashed: Catmull-Rom τ = 1/2 (C¹)</source>
            <translation>discontínua: Catmull-Rom τ = 1/2 (C¹)</translation>
        </message>
        <message>
            <source>natural</source>
            <translation>naturals</translation>
        </message>
        <message>
            <source>not-a-knot</source>
            <translation>sense nus (not-a-knot)</translation>
        </message>
        <message>
            <source>periodic (closed)</source>
            <translation>periòdics (tancada)</translation>
        </message>
        <message>
            <source>uniform</source>
            <translation>uniformes</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::PlaneSplinePanel</name>
        <message>
            <source>&amp;Final tangent:</source>
            <translation>Tangent &amp;final:</translation>
        </message>
        <message>
            <source>&amp;Initial tangent:</source>
            <translation>Tan&amp;gent inicial:</translation>
        </message>
        <message>
            <source>A tangent component is a number between −%1 and %1, such as 1/2 or -0.25.</source>
            <translation>Cada component d&apos;una tangent és un nombre entre −%1 i %1, com ara 1/2 o -0,25.</translation>
        </message>
        <message>
            <source>Catmull-Rom comparison</source>
            <translation>Comparació amb Catmull-Rom</translation>
        </message>
        <message>
            <source>Catmull-Rom τ = 1/2 of the same points</source>
            <translation>Catmull-Rom τ = 1/2 dels mateixos punts</translation>
        </message>
        <message>
            <source>C² spline end tangents</source>
            <translation>Tangents als extrems de l&apos;spline C²</translation>
        </message>
        <message>
            <source>C² spline ends</source>
            <translation>Extrems de l&apos;spline C²</translation>
        </message>
        <message>
            <source>C² spline parameters</source>
            <translation>Paràmetres de l&apos;spline C²</translation>
        </message>
        <message>
            <source>Def 2.1 leaves two conditions free; the ends fix them. Natural: p″ = 0 at both ends. Clamped: the given end tangents. Not-a-knot: p‴ continuous at the second and last but one points. Periodic: a closed curve, C² at every point.</source>
            <translation>La Def. 2.1 deixa dues condicions lliures; els extrems les fixen. Naturals: p″ = 0 als dos extrems. Subjectes: les tangents donades. Sense nus: p‴ contínua al segon i al penúltim punt. Periòdics: una corba tancada, C² a tots els punts.</translation>
        </message>
        <message>
            <source>End c&amp;onditions:</source>
            <translation>Condicions als extre&amp;ms:</translation>
        </message>
        <message>
            <source>Final tangent, %1</source>
            <translation>Tangent final, %1</translation>
        </message>
        <message>
            <source>How the parameter advances from point to point: by 1 (uniform), by the distance (chord length) or by its square root (centripetal).</source>
            <translation>Com avança el paràmetre d&apos;un punt al següent: d&apos;1 en 1 (uniformes), per la distància (longitud de corda) o per la seva arrel quadrada (centrípeta).</translation>
        </message>
        <message>
            <source>Initial tangent, %1</source>
            <translation>Tangent inicial, %1</translation>
        </message>
        <message>
            <source>Knot spacin&amp;g:</source>
            <translation>Espa&amp;iat dels nusos:</translation>
        </message>
        <message>
            <source>x component</source>
            <translation>component x</translation>
        </message>
        <message>
            <source>y component</source>
            <translation>component y</translation>
        </message>
    </context>
    <context>
        <name>granota::ui::SplineFamilyPanels</name>
        <message>
            <source>C² spline in the plane</source>
            <translation>Spline C² al pla</translation>
        </message>
        <message>
            <source>Data where the natural spline dips about 98 below its neighbouring values (d3-shape issue #38); the monotone schemes do not.</source>
            <translation>Dades on l&apos;spline natural baixa unes 98 unitats per sota dels valors veïns (d3-shape, issue #38); els esquemes monòtons, no.</translation>
        </message>
        <message>
            <source>Example: d3-s&amp;hape #38 data</source>
            <translation>Exemple: dades de d3-s&amp;hape #38</translation>
        </message>
        <message>
            <source>Example: t&amp;he frog&apos;s outline points</source>
            <translation>Exemple: punts de la silueta de la gran&amp;ota</translation>
        </message>
        <message>
            <source>Frog outline example</source>
            <translation>Exemple de la silueta de la granota</translation>
        </message>
        <message>
            <source>Function data</source>
            <translation>Dades d&apos;una funció</translation>
        </message>
        <message>
            <source>The frog body&apos;s vertices at rest, closed: the C² spline against the Catmull-Rom outline of §4.12.</source>
            <translation>Els vèrtexs del cos de la granota en repòs, tancats: l&apos;spline C² davant de la silueta de Catmull-Rom del §4.12.</translation>
        </message>
        <message>
            <source>d3-shape #38 example</source>
            <translation>Exemple de d3-shape #38</translation>
        </message>
    </context>
    <context>
        <name>FamilyReport</name>
        <message numerus="yes">
            <source>… and %n more segments.</source>
            <translation>
                <numerusform>… i %n segment més.</numerusform>
                <numerusform>… i %n segments més.</numerusform>
            </translation>
        </message>
        <message>
            <source>Centripetal and chordal spacing: values in decimals.</source>
            <translation>Espaiat centrípet o de corda: valors en decimals.</translation>
        </message>
        <message>
            <source>Def 2.8 with the tangents you set: drag the handle at the end of each tangent.</source>
            <translation>Def. 2.8 amb les tangents que fixeu: arrossegueu la nansa de l&apos;extrem de cada tangent.</translation>
        </message>
        <message>
            <source>Each point has two tangents (Kochanek and Bartels 1984): in ends the segment arriving, out starts the segment leaving; they differ when C ≠ 0, and the curve is then not C¹ there.</source>
            <translation>Cada punt té dues tangents (Kochanek i Bartels 1984): la d&apos;entrada acaba el segment que hi arriba, la de sortida comença el que en surt; són diferents quan C ≠ 0, i aleshores la corba no és C¹ en aquell punt.</translation>
        </message>
        <message>
            <source>Function data y(x): the natural spline, Catmull-Rom, Fritsch–Carlson and Steffen on the same data, their overshoot shaded on the canvas and measured in their panel. This panel lists the exact tangents and segments of the cardinal, Kochanek–Bartels and Hermite families.</source>
            <translation>Dades d&apos;una funció y(x): l&apos;spline natural, Catmull-Rom, Fritsch–Carlson i Steffen sobre les mateixes dades, amb el que sobresurten ombrejat al llenç i mesurat al seu quadre. Aquest quadre llista les tangents i els segments exactes de les famílies cardinal, Kochanek–Bartels i Hermite.</translation>
        </message>
        <message>
            <source>Segments as Hermite data (Def 2.8)</source>
            <translation>Segments com a dades d&apos;Hermite (Def. 2.8)</translation>
        </message>
        <message>
            <source>Segments as cubic Bézier curves</source>
            <translation>Segments com a corbes de Bézier cúbiques</translation>
        </message>
        <message>
            <source>Tangents at the points</source>
            <translation>Tangents als punts</translation>
        </message>
        <message>
            <source>The C² spline in the plane (Def 2.1) solves for its tangents: its end conditions and parameters are in its panel, the continuity at every knot in the Knots tab. This panel lists the exact tangents and segments of the cardinal, Kochanek–Bartels and Hermite families.</source>
            <translation>L&apos;spline C² al pla (Def. 2.1) calcula les seves tangents: les condicions als extrems i els paràmetres són al seu quadre, i la continuïtat a cada nus, a la pestanya Nusos. Aquest quadre llista les tangents i els segments exactes de les famílies cardinal, Kochanek–Bartels i Hermite.</translation>
        </message>
        <message>
            <source>The points or the tangents are not small fractions: values in decimals.</source>
            <translation>Els punts o les tangents no són fraccions petites: valors en decimals.</translation>
        </message>
        <message>
            <source>The tangent at qᵢ is τ(qᵢ₊₁ − qᵢ₋₁) with τ = (1 − c)/2 = %1 (c = %2).</source>
            <translation>La tangent a qᵢ és τ(qᵢ₊₁ − qᵢ₋₁) amb τ = (1 − c)/2 = %1 (c = %2).</translation>
        </message>
        <message>
            <source>in</source>
            <translation>entrada</translation>
        </message>
        <message>
            <source>out</source>
            <translation>sortida</translation>
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
            <translation>La Def. 2.1 al pla: cada segment pᵢ(s) de qᵢ a qᵢ₊₁, s ∈ [0, 1], en potències de s, resolt exactament; la corba és C² a tots els nusos (la pestanya Nusos).</translation>
        </message>
    </context>
</TS>
