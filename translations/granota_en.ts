<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
<context>
    <name>granota::ui::MainWindow</name>
    <message>
        <location filename="../ui/main_window.cpp" line="36"/>
        <source>Granota</source>
        <translation>Granota</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="37"/>
        <source>De Casteljau</source>
        <translation>De Casteljau</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="37"/>
        <source>Bernstein</source>
        <translation>Bernstein</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="37"/>
        <source>Fitting</source>
        <translation>Fitting</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="37"/>
        <source>Catmull-Rom</source>
        <translation>Catmull-Rom</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="37"/>
        <source>Frog</source>
        <translation>Frog</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="38"/>
        <source>§2.1.1, Def 2.4</source>
        <translation>§2.1.1, Def 2.4</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="38"/>
        <source>§2.1.2, Def 2.5</source>
        <translation>§2.1.2, Def 2.5</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="38"/>
        <source>§2.1.3, Lemma 2.2</source>
        <translation>§2.1.3, Lemma 2.2</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="39"/>
        <source>§2.2, Def 2.10</source>
        <translation>§2.2, Def 2.10</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="39"/>
        <source>Chapter 4, Annex II</source>
        <translation>Chapter 4, Annex II</translation>
    </message>
</context>
</TS>
