<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="da_DK">
<context>
    <name>Autosave</name>
    <message>
        <location filename="../../ui/window/autosave.cpp" line="+43" />
        <source>Autosave failed: %1</source>
        <translation>Automatisk gemning mislykkedes: %1</translation>
    </message>
    <message>
        <location line="+14" />
        <source>a new scene that was never saved</source>
        <translation>en ny scene, der aldrig er blevet gemt</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 (in %2)</source>
        <translation>%1 (i %2)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>LagrangeLab did not close normally while %1 had unsaved edits (autosaved %2).</source>
        <translation>LagrangeLab blev ikke lukket normalt, mens %1 havde ændringer, der ikke var gemt (automatisk gemt %2).</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1 no longer exists: the recovered scene is all that is left of it.</source>
        <translation>%1 findes ikke længere: den gendannede scene er alt, hvad der er tilbage af den.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Warning: %1 has changed on disk since these edits were made. Restoring puts the recovered scene on top of the file as it is now; undo returns to it.</source>
        <translation>Advarsel: %1 er blevet ændret på disken, siden disse ændringer blev foretaget. Gendannelse lægger den gendannede scene oven på filen, som den ser ud nu; Fortryd bringer dig tilbage til filen.</translation>
    </message>
    <message>
        <location line="+11" />
        <source>What the edits change:</source>
        <translation>Ændringerne omfatter:</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Restore unsaved edits</source>
        <translation>Gendan ikke-gemte ændringer</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Restore unsaved work?</source>
        <translation>Gendan ikke-gemt arbejde?</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Restore the edits</source>
        <translation>Gendan ændringerne</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+9" />
        <source>Discard them</source>
        <translation>Kassér dem</translation>
    </message>
    <message>
        <location line="-8" />
        <location line="+9" />
        <source>Keep for later</source>
        <translation>Behold til senere</translation>
    </message>
    <message>
        <location line="-2" />
        <source>Open them in a new window</source>
        <translation>Åbn dem i et nyt vindue</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Restore unsaved work</source>
        <translation>Gendan ikke-gemt arbejde</translation>
    </message>
</context>
<context>
    <name>ControlTuning</name>
    <message>
        <location filename="../../ui/window/control_tuning.cpp" line="+80" />
        <source>Controller gains × %1</source>
        <translation>Regulatorens forstærkninger × %1</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Payload the controller believes in: %1 kg</source>
        <translation>Nyttelast, som regulatoren regner med: %1 kg</translation>
    </message>
</context>
<context>
    <name>DerivationPanel</name>
    <message>
        <location filename="../../ui/window/derivation_panel.cpp" line="+108" />
        <source>Deriving…</source>
        <translation>Udleder…</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Derivation stopped: the model is being edited</source>
        <translation>Udledningen er stoppet: modellen er ved at blive redigeret</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The derivation stopped: %1</source>
        <translation>Udledningen stoppede: %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Derived in %1 ms</source>
        <translation>Udledt på %1 ms</translation>
    </message>
</context>
<context>
    <name>DerivationView</name>
    <message>
        <location filename="../../ui/window/derivation_view.cpp" line="+59" />
        <source>Previous</source>
        <translation>Forrige</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Next</source>
        <translation>Næste</translation>
    </message>
    <message>
        <location line="+118" />
        <source>No scene</source>
        <translation>Ingen scene</translation>
    </message>
    <message>
        <location line="-89" />
        <source>DH parameters</source>
        <translation>DH-parametre</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Results at the teach pose</source>
        <translation>Resultater i teach-stillingen</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Step %1: %2</source>
        <translation>Trin %1: %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 (steps 1–5 are a robot's)</source>
        <translation>%1 (trin 1–5 hører til en robot)</translation>
    </message>
    <message>
        <location line="+49" />
        <location line="+22" />
        <location line="+11" />
        <source>Deriving…</source>
        <translation>Udleder…</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Error: %1</source>
        <translation>Fejl: %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 (%2 form)</source>
        <translation>%1 (%2 form)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>structured</source>
        <translation>struktureret</translation>
    </message>
    <message>
        <location line="+0" />
        <source>expanded</source>
        <translation>ekspanderet</translation>
    </message>
</context>
<context>
    <name>DhAxesPanel</name>
    <message>
        <location filename="../../ui/window/dh_axes_panel.cpp" line="+63" />
        <source>« The axes</source>
        <translation>« Akserne</translation>
    </message>
    <message>
        <location line="+1" />
        <source>◀ Previous rule</source>
        <translation>◀ Forrige regel</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Next rule ▶</source>
        <translation>Næste regel ▶</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The table »</source>
        <translation>Tabellen »</translation>
    </message>
    <message>
        <location line="+30" />
        <source>A typed Lagrangian has no joint axes: finding the DH parameters needs a robot.</source>
        <translation>En indtastet Lagrange-funktion har ingen ledakser: DH-parametrene kan kun findes for en robot.</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Rule %1 of %2</source>
        <translation>Regel %1 af %2</translation>
    </message>
    <message>
        <location line="+15" />
        <source>The joint axes</source>
        <translation>Leddenes akser</translation>
    </message>
    <message>
        <location line="+2" />
        <source>The robot stands at home (all q = 0). Joint i turns about (or slides along) its axis, the line marked q&lt;sub&gt;i&lt;/sub&gt;. The rules now place frames 0 to %1 on these lines, one rule at a time: z, then the origin o, then x, then y.</source>
        <translation>Robotten står i hjemmestillingen (alle q = 0). Led i drejer om (eller glider langs) sin akse, linjen mærket q&lt;sub&gt;i&lt;/sub&gt;. Reglerne placerer nu koordinatsystemerne 0 til %1 på disse linjer, én regel ad gangen: z, så origo o, så x, så y.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Frame %1: z</source>
        <translation>Koordinatsystem %1: z</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Frame %1 is the tool's: %2 is taken along the last joint's axis.</source>
        <translation>Koordinatsystem %1 er værktøjets: %2 lægges langs det sidste leds akse.</translation>
    </message>
    <message>
        <location line="+2" />
        <location line="+5" />
        <source>%1 lies on the axis of joint %2, pointing the way q&lt;sub&gt;%2&lt;/sub&gt; turns it (right-hand rule) or slides it.</source>
        <translation>%1 ligger på aksen for led %2 og peger i den retning, som q&lt;sub&gt;%2&lt;/sub&gt; drejer (højrehåndsreglen) eller forskyder leddet.</translation>
    </message>
    <message>
        <location line="-2" />
        <source>%1 lies on the axis of joint 1: frame 0 is frame 1 at home as far as the rules allow.</source>
        <translation>%1 ligger på aksen for led 1: koordinatsystem 0 falder sammen med koordinatsystem 1 i hjemmestillingen, så vidt reglerne tillader det.</translation>
    </message>
    <message>
        <location line="+8" />
        <source>the axis of joint %1</source>
        <translation>aksen for led %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Frame %1: the origin</source>
        <translation>Koordinatsystem %1: origo</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 may lie anywhere on %2: it is taken where %2 comes nearest to the world's origin.</source>
        <translation>%1 må ligge hvor som helst på %2: det lægges, hvor %2 kommer nærmest verdenskoordinatsystemets origo.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 is put at the tool's origin.</source>
        <translation>%1 lægges i værktøjets origo.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 is where %2 meets %3, so d&lt;sub&gt;%4&lt;/sub&gt; = 0.</source>
        <translation>%1 ligger, hvor %2 skærer %3, så d&lt;sub&gt;%4&lt;/sub&gt; = 0.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 and %2 are skew: they have exactly one common normal (the magenta line). %3 is where it meets %4.</source>
        <translation>%1 og %2 er vindskæve: de har netop én fælles normal (den magentafarvede linje). %3 ligger, hvor den skærer %4.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 and %2 intersect: %3 is where they meet, so a&lt;sub&gt;%4&lt;/sub&gt; = 0.</source>
        <translation>%1 og %2 skærer hinanden: %3 er, hvor de mødes, så a&lt;sub&gt;%4&lt;/sub&gt; = 0.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 and %2 are parallel: every normal to one is normal to the other, so the rule leaves the origin free. Chosen: the normal through the previous origin, so d&lt;sub&gt;%3&lt;/sub&gt; = 0.</source>
        <translation>%1 og %2 er parallelle: enhver normal til den ene er normal til den anden, så reglen lader origo være frit. Valgt: normalen gennem det forrige origo, så d&lt;sub&gt;%3&lt;/sub&gt; = 0.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1 and %2 lie on one line: %3 stays at the previous origin (a = 0 and d = 0 between them).</source>
        <translation>%1 og %2 ligger på samme linje: %3 bliver i det forrige origo (a = 0 og d = 0 mellem dem).</translation>
    </message>
    <message>
        <location line="+8" />
        <source>The two axes point opposite ways: α = 180°. z is never turned round to avoid it, or q would turn the joint the other way.</source>
        <translation>De to akser peger i modsat retning: α = 180°. z vendes aldrig om for at undgå det, for så ville q dreje leddet den anden vej.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Frame %1: x</source>
        <translation>Koordinatsystem %1: x</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 is any direction perpendicular to %2: the world's x (or y) made perpendicular, so frame 0 matches the world where it can.</source>
        <translation>%1 er en vilkårlig retning vinkelret på %2: verdenskoordinatsystemets x (eller y) gjort vinkelret, så koordinatsystem 0 så vidt muligt falder sammen med verdenskoordinatsystemet.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 points from the last axis to the tool's origin (along %2 when the tool's origin is on that axis).</source>
        <translation>%1 peger fra den sidste akse mod værktøjets origo (langs %2, når værktøjets origo ligger på aksen).</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 = %2 (made perpendicular to %3), so θ&lt;sub&gt;%4&lt;/sub&gt; = 0 at home.</source>
        <translation>%1 = %2 (gjort vinkelret på %3), så θ&lt;sub&gt;%4&lt;/sub&gt; = 0 i hjemmestillingen.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 is perpendicular to both axes: ±(%2 × %3). The sign is a choice: the one that keeps θ = 0 at home.</source>
        <translation>%1 er vinkelret på begge akser: ±(%2 × %3). Fortegnet er et valg: det, der giver θ = 0 i hjemmestillingen.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 is free around the one line: kept as %2, so θ = 0.</source>
        <translation>%1 kan frit drejes om den fælles linje: den beholdes som %2, så θ = 0.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 lies along the common normal, pointing from %2 to %3.</source>
        <translation>%1 ligger langs den fælles normal og peger fra %2 mod %3.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 lies along the common normal, pointing from %2 to the axis of joint %3.</source>
        <translation>%1 ligger langs den fælles normal og peger fra %2 mod aksen for led %3.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Frame %1: y</source>
        <translation>Koordinatsystem %1: y</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 = %2 × %3 completes a right-handed frame.</source>
        <translation>%1 = %2 × %3 fuldender et højrehåndet koordinatsystem.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Row %1 of the table is read off frames %2 and %1.</source>
        <translation>Række %1 i tabellen aflæses ud fra koordinatsystem %2 og %1.</translation>
    </message>
    <message>
        <location line="+10" />
        <source>The scene's own table is the one the rules give.</source>
        <translation>Scenens egen tabel er den, reglerne giver.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The scene's own table differs in row(s) %1: the rules leave choices (an origin on parallel axes, a sign of x) that the scene made another way. Both describe the same robot.</source>
        <translation>Scenens egen tabel afviger i række(r) %1: reglerne lader valg stå åbne (et origo på parallelle akser, fortegnet på x), som scenen har truffet anderledes. Begge beskriver den samme robot.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Frame 0 is not the world's frame: a base transform, which DH cannot express, places it.</source>
        <translation>Koordinatsystem 0 er ikke verdenskoordinatsystemet: en basistransformation, som DH ikke kan udtrykke, placerer det.</translation>
    </message>
</context>
<context>
    <name>DhStepPage</name>
    <message>
        <location filename="../../ui/window/dh_step_page.cpp" line="+16" />
        <source>Find the DH parameters</source>
        <translation>Find DH-parametrene</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Row by row</source>
        <translation>Række for række</translation>
    </message>
</context>
<context>
    <name>DhStepPanel</name>
    <message>
        <location filename="../../ui/window/dh_step_panel.cpp" line="+58" />
        <source>Joint i</source>
        <translation>Led i</translation>
    </message>
    <message>
        <location line="+1" />
        <source>◀ Previous motion</source>
        <translation>◀ Forrige bevægelse</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Next motion ▶</source>
        <translation>Næste bevægelse ▶</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Animate the next motion</source>
        <translation>Animér den næste bevægelse</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Every parameter on the robot</source>
        <translation>Alle parametre på robotten</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Each row's θ, d, a and α drawn as arcs and arrows with their values, at the pose shown</source>
        <translation>Hver rækkes θ, d, a og α tegnet som buer og pile med deres værdier, i den viste stilling</translation>
    </message>
    <message>
        <location line="+74" />
        <source>A typed Lagrangian has no DH table: the step-through shows a robot's rows.</source>
        <translation>En indtastet Lagrange-funktion har ingen DH-tabel: gennemgangen viser en robots rækker.</translation>
    </message>
    <message>
        <location line="+44" />
        <source>Frame %1 becomes frame %2 by four motions, each along or about an axis of the moving frame.</source>
        <translation>Koordinatsystem %1 bliver til koordinatsystem %2 ved fire bevægelser, hver langs eller om en akse i det bevægede koordinatsystem.</translation>
    </message>
    <message>
        <location line="+9" />
        <source>(q&lt;sub&gt;%1&lt;/sub&gt; included)</source>
        <translation>(q&lt;sub&gt;%1&lt;/sub&gt; medregnet)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>next</source>
        <translation>næste</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Motions done: %1 of 4</source>
        <translation>Udførte bevægelser: %1 af 4</translation>
    </message>
    <message>
        <location line="+10" />
        <source>lengths in m</source>
        <translation>længder i m</translation>
    </message>
</context>
<context>
    <name>EnergyInset</name>
    <message>
        <location filename="../../ui/paint/energy_inset.cpp" line="+153" />
        <source>%1 J</source>
        <translation>%1 J</translation>
    </message>
</context>
<context>
    <name>EntryLinking</name>
    <message>
        <location filename="../../ui/window/entry_linking.cpp" line="+36" />
        <source>Click an entry of the derivation (b11, g2, …) or a link in the 3D view to see what feeds it and its value now.</source>
        <translation>Klik på et element i udledningen (b11, g2, …) eller på et link i 3D-visningen for at se, hvad der bidrager til det, og dets aktuelle værdi.</translation>
    </message>
</context>
<context>
    <name>EntryList</name>
    <message>
        <location filename="../../ui/window/entry_list.cpp" line="+86" />
        <source>Find an entry: b11, g2, beta, p_c…</source>
        <translation>Find et element: b11, g2, beta, p_c…</translation>
    </message>
</context>
<context>
    <name>EntryListModel</name>
    <message>
        <location line="-12" />
        <source>entry</source>
        <translation>element</translation>
    </message>
    <message>
        <location line="+1" />
        <source>value now</source>
        <translation>aktuel værdi</translation>
    </message>
    <message>
        <location line="+1" />
        <source>unit</source>
        <translation>enhed</translation>
    </message>
    <message>
        <location line="+1" />
        <source>links</source>
        <translation>links</translation>
    </message>
</context>
<context>
    <name>EntrySelection</name>
    <message numerus="yes">
        <location filename="../../ui/document/entry_selection.cpp" line="+200" />
        <source>%1 picked: it feeds %n entries of the derivation, marked in the list and the typeset view</source>
        <translation>
            <numerusform>%1 valgt: det indgår i %n element i udledningen, markeret i listen og i den typesatte visning</numerusform>
            <numerusform>%1 valgt: det indgår i %n elementer i udledningen, markeret i listen og i den typesatte visning</numerusform>
        </translation>
    </message>
    <message>
        <location line="+7" />
        <source>at the teach pose</source>
        <translation>i teach-stillingen</translation>
    </message>
    <message>
        <location line="+0" />
        <source>at t = %1 s</source>
        <translation>ved t = %1 s</translation>
    </message>
    <message>
        <location line="+14" />
        <source>the motor's armature</source>
        <translation>motorens rotorinerti</translation>
    </message>
    <message>
        <location line="+0" />
        <source>the springs</source>
        <translation>fjedrene</translation>
    </message>
    <message>
        <location line="+2" />
        <source>no link's parameters occur in it</source>
        <translation>ingen linkparametre indgår i det</translation>
    </message>
    <message>
        <location line="+0" />
        <source>fed by %1</source>
        <translation>bidrag fra %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>depends on %1</source>
        <translation>afhænger af %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>with the velocities %1</source>
        <translation>med hastighederne %1</translation>
    </message>
</context>
<context>
    <name>ExampleGallery</name>
    <message>
        <location filename="../../ui/window/example_gallery.cpp" line="+21" />
        <source>Example gallery</source>
        <translation>Eksempelgalleri</translation>
    </message>
</context>
<context>
    <name>ExerciseMode</name>
    <message>
        <location filename="../../ui/window/exercise_mode.cpp" line="+39" />
        <source>Answers cannot be checked for this scene: %1</source>
        <translation>Svarene kan ikke tjekkes for denne scene: %1</translation>
    </message>
    <message>
        <location line="+17" />
        <source>Practise step %1</source>
        <translation>Øv trin %1</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Practise %1</source>
        <translation>Øv %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>End the exercise</source>
        <translation>Afslut øvelsen</translation>
    </message>
    <message>
        <location line="+15" />
        <source>Making the answer key (the derivation, entry by entry)…</source>
        <translation>Facitlisten laves (udledningen, element for element)…</translation>
    </message>
    <message>
        <location line="+50" />
        <location line="+16" />
        <source>Step %1: %2</source>
        <translation>Trin %1: %2</translation>
    </message>
    <message>
        <location line="-3" />
        <source>Entries not in this derivation</source>
        <translation>Elementer, som ikke findes i denne udledning</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The answer key is being made…</source>
        <translation>Facitlisten laves…</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Step %1</source>
        <translation>Trin %1</translation>
    </message>
    <message>
        <location line="+35" />
        <source>Answer %1</source>
        <translation>Svar %1</translation>
    </message>
</context>
<context>
    <name>ExercisePanel</name>
    <message>
        <location filename="../../ui/window/exercise_panel.cpp" line="+92" />
        <source>Practise this step</source>
        <translation>Øv dette trin</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Hide the answers of the step chosen in the derivation and answer them here</source>
        <translation>Skjul svarene i det trin, der er valgt i udledningen, og besvar dem her</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Practise the picked entry</source>
        <translation>Øv det valgte element</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Hide the entry picked in the derivation, the entry list or the teach panel</source>
        <translation>Skjul elementet, der er valgt i udledningen, elementlisten eller teach-panelet</translation>
    </message>
    <message>
        <location line="+1" />
        <source>End the exercise</source>
        <translation>Afslut øvelsen</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Show every answer again and remove the answers typed (undoable)</source>
        <translation>Vis alle svar igen, og fjern de indtastede svar (kan fortrydes)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Choose a step (or pick an entry) to practise: its answers are hidden in the derivation, and you type your own here. Check says whether yours is right and, if not, where it goes wrong; the answers are saved with the scene.</source>
        <translation>Vælg et trin (eller et element) at øve: svarene skjules i udledningen, og du skriver dine egne her. Tjek siger, om dit svar er rigtigt, og hvis ikke, hvor det går galt; svarene gemmes med scenen.</translation>
    </message>
    <message>
        <location line="+4" />
        <location line="+11" />
        <source>your %1 (c2, q1, m2 lc2^2, …)</source>
        <translation>dit %1 (c2, q1, m2 lc2^2, …)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Check</source>
        <translation>Tjek</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Reveal</source>
        <translation>Vis svaret</translation>
    </message>
    <message>
        <location line="+105" />
        <source>read as: %1</source>
        <translation>læst som: %1</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Right.</source>
        <translation>Rigtigt.</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Wrong.</source>
        <translation>Forkert.</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Cannot read it:</source>
        <translation>Kan ikke læses:</translation>
    </message>
    <message>
        <location line="+12" />
        <source>The right answer: %1</source>
        <translation>Det rigtige svar: %1</translation>
    </message>
    <message>
        <location line="+15" />
        <source>%1 — %2 of %3 right</source>
        <translation>%1 — %2 af %3 rigtige</translation>
    </message>
</context>
<context>
    <name>ExportActions</name>
    <message>
        <location filename="../../ui/window/export_actions.cpp" line="+53" />
        <source>Screenshot (PNG)…</source>
        <translation>Skærmbillede (PNG)…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Plot (PNG, SVG or CSV)…</source>
        <translation>Graf (PNG, SVG eller CSV)…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Derivation (PDF, SVG, PNG, LaTeX or text)…</source>
        <translation>Udledning (PDF, SVG, PNG, LaTeX eller tekst)…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Animation (MP4, WebM, GIF)…</source>
        <translation>Animation (MP4, WebM, GIF)…</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Video for slides, %1×%2 (3D view, equation, energy)…</source>
        <translation>Video til slides, %1×%2 (3D-visning, ligning, energi)…</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Lab report (PDF, CSV, SVG plots, scene, video) into a folder…</source>
        <translation>Laboratorierapport (PDF, CSV, SVG-plot, scene, video) i en mappe…</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Save screenshot</source>
        <translation>Gem skærmbillede</translation>
    </message>
    <message>
        <location line="+0" />
        <source>PNG images (*.png)</source>
        <translation>PNG-billeder (*.png)</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Screenshot</source>
        <translation>Skærmbillede</translation>
    </message>
    <message>
        <location line="+6" />
        <location line="+2" />
        <source>Export plot</source>
        <translation>Eksportér graf</translation>
    </message>
    <message>
        <location line="-2" />
        <source>PNG (*.png);;SVG (*.svg);;CSV (*.csv)</source>
        <translation>PNG (*.png);;SVG (*.svg);;CSV (*.csv)</translation>
    </message>
    <message>
        <location line="+8" />
        <location line="+7" />
        <source>Export derivation</source>
        <translation>Eksportér udledning</translation>
    </message>
    <message>
        <location line="-6" />
        <source>PDF, typeset (*.pdf);;SVG, typeset, a file per page (*.svg);;PNG, typeset, a file per page (*.png);;LaTeX (*.tex);;Text (*.txt)</source>
        <translation>PDF, typesat (*.pdf);;SVG, typesat, én fil pr. side (*.svg);;PNG, typesat, én fil pr. side (*.png);;LaTeX (*.tex);;Tekst (*.txt)</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Export video for slides</source>
        <translation>Eksportér video til slides</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Export animation</source>
        <translation>Eksportér animation</translation>
    </message>
    <message>
        <location line="+2" />
        <source>MP4 (*.mp4);;WebM (*.webm);;GIF (*.gif);;PNG still (*.png)</source>
        <translation>MP4 (*.mp4);;WebM (*.webm);;GIF (*.gif);;PNG-stillbillede (*.png)</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Lab report: choose or make a folder</source>
        <translation>Laboratorierapport: vælg eller opret en mappe</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Lab report</source>
        <translation>Laboratorierapport</translation>
    </message>
    <message>
        <location line="+8" />
        <location line="+77" />
        <source>nothing to export: the simulation has not finished</source>
        <translation>intet at eksportere: simuleringen er ikke færdig</translation>
    </message>
    <message>
        <location line="-70" />
        <source>Plot written to %1</source>
        <translation>Grafen er skrevet til %1</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Written: %1</source>
        <translation>Skrevet: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Export</source>
        <translation>Eksportér</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Export of %1 stopped: %2</source>
        <translation>Eksporten af %1 blev afbrudt: %2</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1: expected a .pdf, .svg, .png, .tex or .txt file</source>
        <translation>%1: forventede en .pdf-, .svg-, .png-, .tex- eller .txt-fil</translation>
    </message>
    <message>
        <location line="+4" />
        <source>nothing to export: the derivation has not finished</source>
        <translation>intet at eksportere: udledningen er ikke færdig</translation>
    </message>
    <message numerus="yes">
        <location line="+21" />
        <source>%1 … %2 (%n pages)</source>
        <translation>
            <numerusform>%1 … %2 (%n side)</numerusform>
            <numerusform>%1 … %2 (%n sider)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3" />
        <source>; 1 page file of an earlier, longer export remains beside it, not deleted: %1</source>
        <translation>; 1 sidefil fra en tidligere, længere eksport ligger stadig ved siden af og er ikke slettet: %1</translation>
    </message>
    <message numerus="yes">
        <location line="+1" />
        <source>; %n page files of an earlier, longer export remain beside it, not deleted: %1</source>
        <translation>
            <numerusform>; %n sidefil fra en tidligere, længere eksport ligger stadig ved siden af og er ikke slettet: %1</numerusform>
            <numerusform>; %n sidefiler fra en tidligere, længere eksport ligger stadig ved siden af og er ikke slettet: %1</numerusform>
        </translation>
    </message>
    <message>
        <location line="+19" />
        <source>Writing %1…</source>
        <translation>Skriver %1…</translation>
    </message>
    <message>
        <location line="+40" />
        <source>Rendering %1…</source>
        <translation>Renderer %1…</translation>
    </message>
    <message>
        <location line="+9" />
        <source>nothing to report yet: the simulation or the derivation has not finished</source>
        <translation>intet at rapportere endnu: simuleringen eller udledningen er ikke færdig</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Writing the lab report into %1…</source>
        <translation>Skriver laboratorierapporten i %1…</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Cancel</source>
        <translation>Annuller</translation>
    </message>
</context>
<context>
    <name>FieldListModel</name>
    <message>
        <location filename="../../ui/document/field_list_model.cpp" line="+53" />
        <source>%1 = %2</source>
        <translation>%1 = %2</translation>
    </message>
    <message>
        <location line="+7" />
        <source>field</source>
        <translation>felt</translation>
    </message>
    <message>
        <location line="+1" />
        <source>value</source>
        <translation>værdi</translation>
    </message>
    <message>
        <location line="+1" />
        <source>unit</source>
        <translation>enhed</translation>
    </message>
</context>
<context>
    <name>FrameOverlay</name>
    <message>
        <location filename="../../ui/paint/frame_overlay.cpp" line="+32" />
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>   (%1× real time)</source>
        <translation>   (%1× realtid)</translation>
    </message>
</context>
<context>
    <name>GhostRun</name>
    <message>
        <location filename="../../ui/window/ghost_run.cpp" line="+23" />
        <source>Ghost run</source>
        <translation>Spøgelseskørsel</translation>
    </message>
    <message>
        <location line="+8" />
        <source>none</source>
        <translation>ingen</translation>
    </message>
</context>
<context>
    <name>JointTableModel</name>
    <message>
        <location filename="../../ui/document/joint_table_model.cpp" line="+76" />
        <source>revolute</source>
        <translation>roterende</translation>
    </message>
    <message>
        <location line="+1" />
        <source>prismatic</source>
        <translation>prismatisk</translation>
    </message>
    <message>
        <location line="+31" />
        <location line="+3" />
        <source>Joint %1: %2 = %3</source>
        <translation>Led %1: %2 = %3</translation>
    </message>
    <message>
        <location line="+13" />
        <source>joint %1</source>
        <translation>led %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>[°]</source>
        <translation>[°]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>[rad]</source>
        <translation>[rad]</translation>
    </message>
    <message>
        <location line="+2" />
        <source>type</source>
        <translation>type</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a [m]</source>
        <translation>a [m]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>α %1</source>
        <translation>α %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>d [m]</source>
        <translation>d [m]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>θ offset %1</source>
        <translation>θ-offset %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>mass [kg]</source>
        <translation>masse [kg]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>COM x [m]</source>
        <translation>massemidtpunkt x [m]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>COM y [m]</source>
        <translation>massemidtpunkt y [m]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>COM z [m]</source>
        <translation>massemidtpunkt z [m]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Ixx [kg·m²]</source>
        <translation>Ixx [kg·m²]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Iyy [kg·m²]</source>
        <translation>Iyy [kg·m²]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Izz [kg·m²]</source>
        <translation>Izz [kg·m²]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Ixy [kg·m²]</source>
        <translation>Ixy [kg·m²]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Ixz [kg·m²]</source>
        <translation>Ixz [kg·m²]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Iyz [kg·m²]</source>
        <translation>Iyz [kg·m²]</translation>
    </message>
    <message>
        <location line="+45" />
        <source>Add joint %1</source>
        <translation>Tilføj led %1</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Remove joint %1</source>
        <translation>Fjern led %1</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Move joint %1 to %2</source>
        <translation>Flyt led %1 til %2</translation>
    </message>
    <message>
        <location line="+33" />
        <source>rod</source>
        <translation>stang</translation>
    </message>
    <message>
        <location line="+1" />
        <source>cylinder</source>
        <translation>cylinder</translation>
    </message>
    <message>
        <location line="+1" />
        <source>disc</source>
        <translation>skive</translation>
    </message>
    <message>
        <location line="+1" />
        <source>box</source>
        <translation>kasse</translation>
    </message>
    <message>
        <location line="+1" />
        <source>sphere</source>
        <translation>kugle</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Joint %1: inertia of a %2</source>
        <translation>Led %1: inerti ud fra formen %2</translation>
    </message>
</context>
<context>
    <name>LanguageMenu</name>
    <message>
        <location filename="../../ui/window/language_menu.cpp" line="+35" />
        <source>&amp;Language</source>
        <translation>&amp;Sprog</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Notation</source>
        <translation>&amp;Notation</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The course notes: B q̈ + C q̇ + g = Q</source>
        <translation>Kursusnoterne: B q̈ + C q̇ + g = Q</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Siciliano: B q̈ + C q̇ + g = τ</source>
        <translation>Siciliano: B q̈ + C q̇ + g = τ</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Spong: D q̈ + C q̇ + g = τ</source>
        <translation>Spong: D q̈ + C q̇ + g = τ</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Craig: M Θ̈ + V + G = τ (modified DH)</source>
        <translation>Craig: M Θ̈ + V + G = τ (modificeret DH)</translation>
    </message>
</context>
<context>
    <name>LessonMode</name>
    <message>
        <location filename="../../ui/window/lesson_mode.cpp" line="+114" />
        <location line="+158" />
        <source>Lesson</source>
        <translation>Lektion</translation>
    </message>
    <message>
        <location line="-157" />
        <source>Add view</source>
        <translation>Tilføj visning</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Update</source>
        <translation>Opdatér</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Remove</source>
        <translation>Fjern</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Present</source>
        <translation>Præsentér</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The speaker's note for this view</source>
        <translation>Talerens note til denne visning</translation>
    </message>
    <message>
        <location line="+16" />
        <source>Edit the note of view %1</source>
        <translation>Redigér noten til visning %1</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Move a view</source>
        <translation>Flyt en visning</translation>
    </message>
    <message>
        <location line="+41" />
        <source>Undo in the lesson</source>
        <translation>Fortryd i lektionen</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Undo in the lesson: %1</source>
        <translation>Fortryd i lektionen: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Redo in the lesson</source>
        <translation>Gentag i lektionen</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Redo in the lesson: %1</source>
        <translation>Gentag i lektionen: %1</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Rename view</source>
        <translation>Omdøb visning</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Title of the view:</source>
        <translation>Visningens titel:</translation>
    </message>
    <message>
        <location line="+9" />
        <source>&amp;Lesson</source>
        <translation>&amp;Lektion</translation>
    </message>
    <message>
        <location line="+1" />
        <source>New lesson</source>
        <translation>Ny lektion</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Open lesson…</source>
        <translation>Åbn lektion…</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+289" />
        <source>Save lesson</source>
        <translation>Gem lektion</translation>
    </message>
    <message>
        <location line="-288" />
        <source>Save lesson as…</source>
        <translation>Gem lektion som…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Add the current view</source>
        <translation>Tilføj den aktuelle visning</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Update the view with the current one</source>
        <translation>Erstat visningen med den aktuelle</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Remove the view</source>
        <translation>Fjern visningen</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Rename the view…</source>
        <translation>Omdøb visningen…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Present the lesson</source>
        <translation>Præsentér lektionen</translation>
    </message>
    <message>
        <location line="+41" />
        <source>Unsaved lesson</source>
        <translation>Lektion ikke gemt</translation>
    </message>
    <message>
        <location line="+0" />
        <source>The lesson has unsaved changes. Save them?</source>
        <translation>Lektionen har ændringer, der ikke er gemt. Vil du gemme dem?</translation>
    </message>
    <message>
        <location line="+25" />
        <source>View %1</source>
        <translation>Visning %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Add view %1</source>
        <translation>Tilføj visning %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Added to the lesson as view %1</source>
        <translation>Tilføjet til lektionen som visning %1</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Update view %1</source>
        <translation>Opdatér visning %1</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Remove view %1</source>
        <translation>Fjern visning %1</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Rename view %1</source>
        <translation>Omdøb visning %1</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Move view %1</source>
        <translation>Flyt visning %1</translation>
    </message>
    <message>
        <location line="+116" />
        <source>unsaved</source>
        <translation>ikke gemt</translation>
    </message>
    <message numerus="yes">
        <location line="+1" />
        <source>&lt;b&gt;%1&lt;/b&gt; (%2) · %n view(s)</source>
        <translation>
            <numerusform>&lt;b&gt;%1&lt;/b&gt; (%2) · %n visning</numerusform>
            <numerusform>&lt;b&gt;%1&lt;/b&gt; (%2) · %n visninger</numerusform>
        </translation>
    </message>
    <message>
        <location line="+15" />
        <source>Speaker notes — LagrangeLab</source>
        <translation>Talernoter — LagrangeLab</translation>
    </message>
    <message>
        <location line="+30" />
        <source>&lt;b&gt;%1&lt;/b&gt; — view %2 of %3</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; — visning %2 af %3</translation>
    </message>
    <message>
        <location line="+1" />
        <source>(no note)</source>
        <translation>(ingen note)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Next: %1</source>
        <translation>Næste: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Last view</source>
        <translation>Sidste visning</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Open lesson</source>
        <translation>Åbn lektion</translation>
    </message>
    <message>
        <location line="+0" />
        <location line="+11" />
        <source>Lessons (*.lesson *.json)</source>
        <translation>Lektioner (*.lesson *.json)</translation>
    </message>
    <message>
        <location line="-8" />
        <source>Cannot open the lesson</source>
        <translation>Lektionen kan ikke åbnes</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Some views could not be read</source>
        <translation>Nogle visninger kunne ikke læses</translation>
    </message>
    <message>
        <location line="+1" />
        <source>They are kept in the lesson as they are written:
%1</source>
        <translation>De bevares i lektionen, som de er skrevet:
%1</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Cannot save the lesson</source>
        <translation>Lektionen kan ikke gemmes</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <location filename="../../ui/window/main_window.cpp" line="+128" />
        <source>Model</source>
        <translation>Model</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Derivation</source>
        <translation>Udledning</translation>
    </message>
    <message>
        <location line="+11" />
        <source>◀ Previous step</source>
        <translation>◀ Forrige trin</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Next step ▶</source>
        <translation>Næste trin ▶</translation>
    </message>
    <message>
        <location line="+8" />
        <source>step %1 (%2 of %3)</source>
        <translation>trin %1 (%2 af %3)</translation>
    </message>
    <message>
        <location line="+20" />
        <source>Typeset</source>
        <translation>Typesat</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Text</source>
        <translation>Tekst</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Entries</source>
        <translation>Elementer</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Exercise</source>
        <translation>Øvelse</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Plots</source>
        <translation>Grafer</translation>
    </message>
    <message>
        <location line="+26" />
        <source>Energy</source>
        <translation>Energi</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Joints q, dq/dt</source>
        <translation>Led q, dq/dt</translation>
    </message>
    <message>
        <location line="+0" />
        <location line="+123" />
        <source>Teach</source>
        <translation>Teach</translation>
    </message>
    <message>
        <location line="-123" />
        <source>Torques</source>
        <translation>Momenter</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Properties</source>
        <translation>Egenskaber</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Work–precision</source>
        <translation>Beregningsarbejde–præcision</translation>
    </message>
    <message>
        <location line="+0" />
        <source>DH step-through</source>
        <translation>DH-gennemgang</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Tracking</source>
        <translation>Banefølgning</translation>
    </message>
    <message>
        <location line="+17" />
        <source>Meshes not read, so the DH drawing is shown: %1</source>
        <translation>Mesh-filer kunne ikke læses, så DH-tegningen vises: %1</translation>
    </message>
    <message>
        <location line="+58" />
        <source>&amp;File</source>
        <translation>&amp;Filer</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Export</source>
        <translation>Eksportér</translation>
    </message>
    <message>
        <location line="+3" />
        <source>&amp;Quit</source>
        <translation>&amp;Afslut</translation>
    </message>
    <message>
        <location line="+3" />
        <source>&amp;Edit</source>
        <translation>&amp;Rediger</translation>
    </message>
    <message>
        <location line="+5" />
        <source>&amp;Undo</source>
        <translation>&amp;Fortryd</translation>
    </message>
    <message>
        <location line="+0" />
        <source>&amp;Undo %1</source>
        <translation>&amp;Fortryd %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Redo</source>
        <translation>&amp;Gentag</translation>
    </message>
    <message>
        <location line="+0" />
        <source>&amp;Redo %1</source>
        <translation>&amp;Gentag %1</translation>
    </message>
    <message>
        <location line="+8" />
        <source>&amp;Simulation</source>
        <translation>&amp;Simulering</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Play / pause</source>
        <translation>Afspil/pause</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Restart</source>
        <translation>Start forfra</translation>
    </message>
    <message>
        <location line="+3" />
        <source>&amp;View</source>
        <translation>&amp;Vis</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Fit view</source>
        <translation>Tilpas visning</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Main</source>
        <translation>Hovedværktøjslinje</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Open</source>
        <translation>Åbn</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save</source>
        <translation>Gem</translation>
    </message>
    <message>
        <location line="+4" />
        <source>▶ Play</source>
        <translation>▶ Afspil</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Present</source>
        <translation>Præsentér</translation>
    </message>
    <message>
        <location line="+60" />
        <source>Simulation failed: %1</source>
        <translation>Simuleringen mislykkedes: %1</translation>
    </message>
    <message>
        <location line="+100" />
        <source>simulating…</source>
        <translation>simulerer…</translation>
    </message>
    <message>
        <location line="+4" />
        <source>dt %1 s</source>
        <translation>dt %1 s</translation>
    </message>
    <message>
        <location line="+0" />
        <source>tol %1</source>
        <translation>tol %1</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 · %2 · %3 steps · |ΔE|/E %4 · %5× real time · simulated in %6 ms</source>
        <translation>%1 · %2 · %3 skridt · |ΔE|/E %4 · %5× realtid · simuleret på %6 ms</translation>
    </message>
    <message numerus="yes">
        <location line="+6" />
        <source> · %n warning(s)</source>
        <translation>
            <numerusform> · %n advarsel</numerusform>
            <numerusform> · %n advarsler</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1" />
        <source> · the model has errors: showing the last valid one</source>
        <translation> · modellen har fejl: viser den seneste gyldige</translation>
    </message>
    <message>
        <location line="+85" />
        <source>%1%2 — LagrangeLab</source>
        <translation>%1%2 — LagrangeLab</translation>
    </message>
</context>
<context>
    <name>ModelEditor</name>
    <message>
        <location filename="../../ui/window/model_editor.cpp" line="+67" />
        <source>DH</source>
        <translation>DH</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Inertials</source>
        <translation>Masse og inerti</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Parameters</source>
        <translation>Parametre</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Initial &amp;&amp; gravity</source>
        <translation>Startværdier &amp;&amp; tyngdekraft</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Solver</source>
        <translation>Løser</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Lagrangian</source>
        <translation>Lagrange-funktion</translation>
    </message>
    <message>
        <location line="+0" />
        <source>JSON</source>
        <translation>JSON</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Checks (errors keep the last valid model on screen):</source>
        <translation>Kontroller (ved fejl bliver den seneste gyldige model stående på skærmen):</translation>
    </message>
    <message>
        <location line="+21" />
        <source>standard (Spong)</source>
        <translation>standard (Spong)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>modified (Craig)</source>
        <translation>modificeret (Craig)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>angles in degrees</source>
        <translation>vinkler i grader</translation>
    </message>
    <message>
        <location line="+1" />
        <source>convention</source>
        <translation>konvention</translation>
    </message>
    <message>
        <location line="+14" />
        <source>Add joint</source>
        <translation>Tilføj led</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+63" />
        <source>Remove</source>
        <translation>Fjern</translation>
    </message>
    <message>
        <location line="-62" />
        <source>Move up</source>
        <translation>Flyt op</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Move down</source>
        <translation>Flyt ned</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Convention: %1</source>
        <translation>Konvention: %1</translation>
    </message>
    <message>
        <location line="+19" />
        <source>rod (length L)</source>
        <translation>stang (længde L)</translation>
    </message>
    <message>
        <location line="+0" />
        <source>cylinder (r, h)</source>
        <translation>cylinder (r, h)</translation>
    </message>
    <message>
        <location line="+0" />
        <source>disc (r)</source>
        <translation>skive (r)</translation>
    </message>
    <message>
        <location line="+0" />
        <source>box (x, y, z)</source>
        <translation>kasse (x, y, z)</translation>
    </message>
    <message>
        <location line="+0" />
        <source>sphere (r)</source>
        <translation>kugle (r)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Fill inertia from shape…</source>
        <translation>Udfyld inerti ud fra form…</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Inertia from a shape</source>
        <translation>Inerti ud fra en form</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Joint %1, %2: dimensions in metres, comma-separated (numbers or parameters)</source>
        <translation>Led %1, %2: dimensioner i meter, adskilt med komma (tal eller parametre)</translation>
    </message>
    <message>
        <location line="+22" />
        <source>Add parameter…</source>
        <translation>Tilføj parameter…</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Rename…</source>
        <translation>Omdøb…</translation>
    </message>
    <message>
        <location line="+8" />
        <location line="+3" />
        <source>Rename parameter</source>
        <translation>Omdøb parameter</translation>
    </message>
    <message>
        <location line="-3" />
        <source>New name of %1 (every expression using it follows):</source>
        <translation>Nyt navn til %1 (alle udtryk, der bruger den, opdateres):</translation>
    </message>
    <message>
        <location line="+8" />
        <location line="+2" />
        <location line="+3" />
        <source>Add parameter</source>
        <translation>Tilføj parameter</translation>
    </message>
    <message>
        <location line="-5" />
        <source>Name (letters, digits, _; e.g. m3, l2, k):</source>
        <translation>Navn (bogstaver, cifre, _; f.eks. m3, l2, k):</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Value of %1 (a number, SI units):</source>
        <translation>Værdi af %1 (et tal i SI-enheder):</translation>
    </message>
    <message>
        <location line="+25" />
        <source>Apply (undoable)</source>
        <translation>Anvend (kan fortrydes)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Edit scene JSON</source>
        <translation>Rediger scenens JSON</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Scene JSON</source>
        <translation>Scenens JSON</translation>
    </message>
    <message>
        <location line="+23" />
        <source>hint: it happened with your edit of %1</source>
        <translation>tip: det skete ved din ændring af %1</translation>
    </message>
    <message>
        <location line="+5" />
        <source>no errors, no warnings</source>
        <translation>ingen fejl, ingen advarsler</translation>
    </message>
    <message>
        <location line="+9" />
        <source>hint: %1 is no longer in %2 but still in %3; to change it everywhere, change %1 under Parameters</source>
        <translation>tip: %1 står ikke længere i %2, men stadig i %3; ret %1 under Parametre for at ændre den overalt</translation>
    </message>
    <message>
        <location line="+46" />
        <source>parameter name '%1': letters, digits and _ only, starting with a letter</source>
        <translation>parameternavn '%1': kun bogstaver, cifre og _, og det skal begynde med et bogstav</translation>
    </message>
    <message>
        <location line="+4" />
        <source>parameter name '%1': there is a parameter of that name</source>
        <translation>parameternavn '%1': der findes allerede en parameter med det navn</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Add parameter %1</source>
        <translation>Tilføj parameter %1</translation>
    </message>
    <message>
        <location line="+7" />
        <source>no parameter '%1'</source>
        <translation>ingen parameter ved navn '%1'</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Rename parameter %1 to %2</source>
        <translation>Omdøb parameter %1 til %2</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Remove parameter %1</source>
        <translation>Fjern parameter %1</translation>
    </message>
</context>
<context>
    <name>PlaybackBar</name>
    <message>
        <location filename="../../ui/window/playback_bar.cpp" line="+48" />
        <source>Play / pause (Space)</source>
        <translation>Afspil/pause (Space)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Restart</source>
        <translation>Start forfra</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Playback time: drag to scrub</source>
        <translation>Afspilningstid: træk for at spole</translation>
    </message>
    <message>
        <location line="+1" />
        <source>×</source>
        <translation>×</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Playback speed (simulated seconds per second)</source>
        <translation>Afspilningshastighed (simulerede sekunder pr. sekund)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>loop</source>
        <translation>gentag</translation>
    </message>
    <message>
        <location line="+1" />
        <source>speed</source>
        <translation>hastighed</translation>
    </message>
    <message>
        <location line="+89" />
        <source>t = %1 s / %2 s</source>
        <translation>t = %1 s / %2 s</translation>
    </message>
</context>
<context>
    <name>PresentationMode</name>
    <message>
        <location filename="../../ui/window/presentation_mode.cpp" line="+32" />
        <source>Presentation mode</source>
        <translation>Præsentationstilstand</translation>
    </message>
</context>
<context>
    <name>PropertiesPanel</name>
    <message>
        <location filename="../../ui/window/properties_panel.cpp" line="+54" />
        <source>Checking the model along the run…</source>
        <translation>Kontrollerer modellen gennem kørslen…</translation>
    </message>
    <message>
        <location line="+9" />
        <source>n/a</source>
        <translation>i/r</translation>
    </message>
    <message>
        <location line="+1" />
        <source>does not apply to a typed Lagrangian (it has no links to recurse over)</source>
        <translation>gælder ikke for en indtastet Lagrange-funktion (der er ingen links at gennemløbe rekursivt)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>pass</source>
        <translation>bestået</translation>
    </message>
    <message>
        <location line="+1" />
        <source>fail</source>
        <translation>ikke bestået</translation>
    </message>
    <message>
        <location line="+2" />
        <source>must stay above</source>
        <translation>skal holde sig over</translation>
    </message>
    <message>
        <location line="+0" />
        <source>tolerance</source>
        <translation>tolerance</translation>
    </message>
    <message>
        <location line="+5" />
        <source>worst at &lt;a href='%1'&gt;t = %2 s&lt;/a&gt;, q = %3</source>
        <translation>værst ved &lt;a href='%1'&gt;t = %2 s&lt;/a&gt;, q = %3</translation>
    </message>
    <message>
        <location line="+9" />
        <source>All %1 properties that apply hold along the run.</source>
        <translation>Alle %1 relevante egenskaber holder gennem hele kørslen.</translation>
    </message>
    <message numerus="yes">
        <location line="+1" />
        <source>%n of the properties fails along the run: see where.</source>
        <translation>
            <numerusform>%n af egenskaberne holder ikke gennem kørslen: se hvor.</numerusform>
            <numerusform>%n af egenskaberne holder ikke gennem kørslen: se hvor.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <location filename="../../ui/document/crash_recovery.cpp" line="+37" />
        <source>(none)</source>
        <translation>(ingen)</translation>
    </message>
    <message>
        <location line="+89" />
        <source>A recovery copy that was cut short was set aside: %1</source>
        <translation>En ufuldstændig gendannelseskopi blev lagt til side: %1</translation>
    </message>
    <message>
        <location line="+28" />
        <source>… and %1 more</source>
        <translation>… og %1 mere</translation>
    </message>
    <message>
        <location filename="../../ui/document/entry_selection.cpp" line="-43" />
        <source>link&amp;nbsp;%1</source>
        <translation>link&amp;nbsp;%1</translation>
    </message>
</context>
<context>
    <name>SceneFiles</name>
    <message>
        <location filename="../../ui/window/scene_files.cpp" line="+27" />
        <source>LagrangeLab scenes (*.lagrange *.json);;All files (*)</source>
        <translation>LagrangeLab-scener (*.lagrange *.json);;Alle filer (*)</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Import a robot from URDF</source>
        <translation>Importér en robot fra URDF</translation>
    </message>
    <message>
        <location line="+0" />
        <source>URDF robots (*.urdf);;All files (*)</source>
        <translation>URDF-robotter (*.urdf);;Alle filer (*)</translation>
    </message>
    <message>
        <location line="+12" />
        <source>&amp;Open…</source>
        <translation>&amp;Åbn…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Import URDF…</source>
        <translation>&amp;Importér URDF…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Examples</source>
        <translation>Eksempler</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Gallery…</source>
        <translation>Galleri…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Recent files</source>
        <translation>Seneste filer</translation>
    </message>
    <message>
        <location line="+12" />
        <source>&amp;Save</source>
        <translation>&amp;Gem</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save &amp;as…</source>
        <translation>Gem &amp;som…</translation>
    </message>
    <message>
        <location line="+26" />
        <source>Cannot import %1</source>
        <translation>Kan ikke importere %1</translation>
    </message>
    <message>
        <location line="+22" />
        <source>%1: another file is being opened</source>
        <translation>%1: en anden fil er ved at blive åbnet</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Opening %1…</source>
        <translation>Åbner %1…</translation>
    </message>
    <message>
        <location line="+17" />
        <source>Cannot open %1</source>
        <translation>Kan ikke åbne %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>The scene has errors; the open scene is kept.</source>
        <translation>Scenen indeholder fejl; den åbne scene bevares.</translation>
    </message>
    <message numerus="yes">
        <location line="+6" />
        <source>%1: %n error(s), nothing changed</source>
        <translation>
            <numerusform>%1: %n fejl, intet er ændret</numerusform>
            <numerusform>%1: %n fejl, intet er ændret</numerusform>
        </translation>
    </message>
    <message>
        <location line="+18" />
        <source>Open scene</source>
        <translation>Åbn scene</translation>
    </message>
    <message>
        <location line="+8" />
        <location line="+11" />
        <source>Save</source>
        <translation>Gem</translation>
    </message>
    <message>
        <location line="-4" />
        <source>Save scene as</source>
        <translation>Gem scene som</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Unsaved changes</source>
        <translation>Ikke-gemte ændringer</translation>
    </message>
    <message>
        <location line="+0" />
        <source>The scene has unsaved changes. Save them?</source>
        <translation>Scenen har ændringer, der ikke er gemt. Vil du gemme dem?</translation>
    </message>
</context>
<context>
    <name>TeachPanel</name>
    <message>
        <location filename="../../ui/window/teach_panel.cpp" line="+42" />
        <source>Teach mode poses robots; this scene is a hand-typed Lagrangian.</source>
        <translation>Teach-tilstanden bruges til at stille robotter i en bestemt stilling; denne scene er en håndindtastet Lagrange-funktion.</translation>
    </message>
    <message>
        <location line="+80" />
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
</context>
<context>
    <name>TorquePane</name>
    <message>
        <location filename="../../ui/window/torque_pane.cpp" line="+39" />
        <source>Where the torque of</source>
        <translation>Hvordan momentet i</translation>
    </message>
    <message>
        <location line="+1" />
        <source>goes: B q̈ + C q̇ + g = Q</source>
        <translation>fordeler sig: B q̈ + C q̇ + g = Q</translation>
    </message>
    <message>
        <location line="+3" />
        <location line="+17" />
        <source>joint %1</source>
        <translation>led %1</translation>
    </message>
    <message>
        <location line="+27" />
        <source>B q̈ (inertial)</source>
        <translation>B q̈ (inerti)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>C q̇ (Coriolis, centrifugal)</source>
        <translation>C q̇ (Coriolis, centrifugal)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>g (gravity, springs)</source>
        <translation>g (tyngdekraft, fjedre)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Q (non-conservative)</source>
        <translation>Q (ikke-konservativ)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Q: actuation</source>
        <translation>Q: aktuering</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Q: viscous friction</source>
        <translation>Q: viskos friktion</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Q: Coulomb friction</source>
        <translation>Q: Coulomb-friktion</translation>
    </message>
    <message>
        <location line="+19" />
        <source>largest |B q̈ + C q̇ + g − Q| of the run: %1%2</source>
        <translation>største |B q̈ + C q̇ + g − Q| i kørslen: %1%2</translation>
    </message>
</context>
<context>
    <name>TrackingPane</name>
    <message>
        <location filename="../../ui/window/tracking_pane.cpp" line="+87" />
        <location line="+35" />
        <source>joint %1</source>
        <translation>led %1</translation>
    </message>
    <message>
        <location line="-27" />
        <source>gains × %1</source>
        <translation>forstærkninger × %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>payload in its model %1 kg</source>
        <translation>nyttelast i regulatorens model %1 kg</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Tracking error e, ė</source>
        <translation>Følgefejl e, ė</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Controller's torque</source>
        <translation>Regulatorens moment</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Lyapunov function V</source>
        <translation>Lyapunov-funktionen V</translation>
    </message>
    <message>
        <location line="+1" />
        <source>dV/dt and −q̇ᵀKd q̇</source>
        <translation>dV/dt og −q̇ᵀKd q̇</translation>
    </message>
    <message>
        <location line="+59" />
        <source>e = qref − q</source>
        <translation>e = qref − q</translation>
    </message>
    <message>
        <location line="+1" />
        <source>ė = q̇ref − q̇</source>
        <translation>ė = q̇ref − q̇</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Joint %1: RMS e = %2 %3, largest |e| = %4 %3.</source>
        <translation>Led %1: RMS e = %2 %3, største |e| = %4 %3.</translation>
    </message>
    <message>
        <location line="+11" />
        <source>B̂ q̈d</source>
        <translation>B̂ q̈d</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Ĉ q̇</source>
        <translation>Ĉ q̇</translation>
    </message>
    <message>
        <location line="+1" />
        <source>ĝ</source>
        <translation>ĝ</translation>
    </message>
    <message>
        <location line="+1" />
        <source>B̂ Kp e</source>
        <translation>B̂ Kp e</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Kp e</source>
        <translation>Kp e</translation>
    </message>
    <message>
        <location line="+1" />
        <source>B̂ Kd ė</source>
        <translation>B̂ Kd ė</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Kd ė</source>
        <translation>Kd ė</translation>
    </message>
    <message>
        <location line="+1" />
        <source>τ applied</source>
        <translation>τ påtrykt</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Joint %1: largest |τ| = %2 %3</source>
        <translation>Led %1: største |τ| = %2 %3</translation>
    </message>
    <message>
        <location line="+2" />
        <source>, limit %1 %2, saturated %3 % of the run</source>
        <translation>, grænse %1 %2, mættet i %3 % af kørslen</translation>
    </message>
    <message>
        <location line="+1" />
        <source> (no actuator: τ = 0)</source>
        <translation> (ingen aktuator: τ = 0)</translation>
    </message>
    <message>
        <location line="+15" />
        <source>V = ½ q̇ᵀB q̇ + ½ eᵀK_p e + E_pot(q) − E_pot(q_ref). </source>
        <translation>V = ½ q̇ᵀB q̇ + ½ eᵀK_p e + E_pot(q) − E_pot(q_ref). </translation>
    </message>
    <message>
        <location line="+1" />
        <source>V = ½ q̇ᵀB q̇ + ½ eᵀK_p e. </source>
        <translation>V = ½ q̇ᵀB q̇ + ½ eᵀK_p e. </translation>
    </message>
    <message>
        <location line="+2" />
        <source>dV/dt = −q̇ᵀK_d q̇ at every instant (largest difference %1 of the largest dissipation) because q̇ᵀ(Ḃ − 2C)q̇ = 0: the skew-symmetry the Properties tab checks. V can only fall.</source>
        <translation>dV/dt = −q̇ᵀK_d q̇ til ethvert tidspunkt (største forskel %1 af den største dissipation), fordi q̇ᵀ(Ḃ − 2C)q̇ = 0: den skævsymmetri, som fanen Egenskaber kontrollerer. V kan kun falde.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>dV/dt departs from −q̇ᵀK_d q̇ (by up to %1 of the largest dissipation): dV/dt + q̇ᵀK_d q̇ = q̇ᵀ(ĝ − g) + the power of friction and of the limits' shortfall. The skew property still holds; the controller's ĝ is not the robot's g, or something else acts.</source>
        <translation>dV/dt afviger fra −q̇ᵀK_d q̇ (med op til %1 af den største dissipation): dV/dt + q̇ᵀK_d q̇ = q̇ᵀ(ĝ − g) + effekten af friktion og af det moment, som momentgrænserne skærer bort. Skævsymmetrien gælder stadig; regulatorens ĝ er ikke robottens g, eller noget andet virker på robotten.</translation>
    </message>
</context>
<context>
    <name>TrajectoryChart</name>
    <message>
        <location filename="../../ui/window/trajectory_chart.cpp" line="+75" />
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>energy [J]</source>
        <translation>energi [J]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>q [rad or m], q̇ [rad/s or m/s]</source>
        <translation>q [rad eller m], q̇ [rad/s eller m/s]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>t</source>
        <translation>t</translation>
    </message>
    <message>
        <location line="+58" />
        <source>E_kin</source>
        <translation>E_kin</translation>
    </message>
    <message>
        <location line="+1" />
        <source>E_pot</source>
        <translation>E_pot</translation>
    </message>
    <message>
        <location line="+1" />
        <source>E</source>
        <translation>E</translation>
    </message>
    <message>
        <location line="+2" />
        <source>W</source>
        <translation>W</translation>
    </message>
    <message>
        <location line="+2" />
        <source>E − W</source>
        <translation>E − W</translation>
    </message>
    <message>
        <location line="+3" />
        <source>E, ghost (%1)</source>
        <translation>E, spøgelse (%1)</translation>
    </message>
</context>
<context>
    <name>ViewBar</name>
    <message>
        <location filename="../../ui/window/view_bar.cpp" line="+33" />
        <source>Fit</source>
        <translation>Tilpas</translation>
    </message>
    <message>
        <location line="+2" />
        <source>front</source>
        <translation>forfra</translation>
    </message>
    <message>
        <location line="+0" />
        <source>side</source>
        <translation>fra siden</translation>
    </message>
    <message>
        <location line="+0" />
        <source>top</source>
        <translation>oppefra</translation>
    </message>
    <message>
        <location line="+0" />
        <source>iso</source>
        <translation>iso</translation>
    </message>
    <message>
        <location line="+10" />
        <source>frames</source>
        <translation>koordinatsystemer</translation>
    </message>
    <message>
        <location line="+1" />
        <source>labels</source>
        <translation>etiketter</translation>
    </message>
    <message>
        <location line="+1" />
        <source>COMs</source>
        <translation>massemidtpunkter</translation>
    </message>
    <message>
        <location line="+1" />
        <source>trail</source>
        <translation>spor</translation>
    </message>
    <message>
        <location line="+1" />
        <source>meshes</source>
        <translation>mesh-filer</translation>
    </message>
</context>
<context>
    <name>ViewState</name>
    <message>
        <location filename="../../ui/window/view_state.cpp" line="+141" />
        <source>The scene open now was kept (its changes are not saved): the view is shown on it.</source>
        <translation>Scenen, der er åben nu, blev beholdt (dens ændringer er ikke gemt): visningen vises på den.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The view's own scene could not be opened; it is shown on the scene open now:</source>
        <translation>Visningens egen scene kunne ikke åbnes; den vises på den scene, der er åben nu:</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The scene %1 could not be opened; the view is shown on the scene open now:</source>
        <translation>Scenen %1 kunne ikke åbnes; visningen vises på den scene, der er åben nu:</translation>
    </message>
    <message>
        <location line="+26" />
        <source>The view is shown as far as it could be</source>
        <translation>Visningen er vist, så langt det var muligt</translation>
    </message>
    <message>
        <location line="+14" />
        <source>The scene's simulation failed (the status line says why): the view is shown without its run.</source>
        <translation>Scenens simulering mislykkedes (statuslinjen siger hvorfor): visningen vises uden dens kørsel.</translation>
    </message>
    <message>
        <location line="+9" />
        <source>The time %1 s is after the run's end (%2 s): the end is shown.</source>
        <translation>Tiden %1 s ligger efter kørslens slutning (%2 s): slutningen vises.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>The derivation has no entry %1 any more: nothing is picked.</source>
        <translation>Udledningen har ikke længere elementet %1: intet er valgt.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The scene has no link %1 (it has %2): no link is picked.</source>
        <translation>Scenen har intet link %1 (den har %2): intet link er valgt.</translation>
    </message>
    <message>
        <location line="+10" />
        <source>The derivation has no step %1 (its steps: %2 to %3): its first step is shown.</source>
        <translation>Udledningen har intet trin %1 (dens trin: %2 til %3): dens første trin vises.</translation>
    </message>
    <message>
        <location line="+23" />
        <source>The scene has no controller, so no Tracking tab: the Energy tab is shown.</source>
        <translation>Scenen har ingen regulator og derfor ingen fane Banefølgning: fanen Energi vises.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The scene has no joint %1 (it has %2): the plots show joint 1.</source>
        <translation>Scenen har intet led %1 (den har %2): graferne viser led 1.</translation>
    </message>
    <message>
        <location line="+7" />
        <source>A typed Lagrangian has no DH table to step through.</source>
        <translation>En indtastet Lagrange-funktion har ingen DH-tabel at gennemgå.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>The robot has no frame %1 (its frames: 0 to %2).</source>
        <translation>Robotten har intet koordinatsystem %1 (dens koordinatsystemer: 0 til %2).</translation>
    </message>
    <message>
        <location line="+5" />
        <source>The robot has no joint %1 (it has %2): the DH step-through shows joint 1.</source>
        <translation>Robotten har intet led %1 (den har %2): DH-gennemgangen viser led 1.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>The teach pose has %1 values, the scene %2 joints: the robot is not posed.</source>
        <translation>Teach-stillingen har %1 værdier, scenen %2 led: robotten stilles ikke.</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Save view…</source>
        <translation>Gem visning…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Open view…</source>
        <translation>Åbn visning…</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Save view</source>
        <translation>Gem visning</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Views (*.json)</source>
        <translation>Visninger (*.json)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>View saved to %1</source>
        <translation>Visningen er gemt i %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Cannot save the view</source>
        <translation>Visningen kan ikke gemmes</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Open view</source>
        <translation>Åbn visning</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Views, lessons and scenes (*.json *.lesson)</source>
        <translation>Visninger, lektioner og scener (*.json *.lesson)</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Cannot open the view</source>
        <translation>Visningen kan ikke åbnes</translation>
    </message>
</context>
<context>
    <name>WorkPrecisionPane</name>
    <message>
        <location filename="../../ui/window/work_precision_pane.cpp" line="+33" />
        <source>Run work–precision sweep</source>
        <translation>Kør gennemløb for beregningsarbejde–præcision</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Cancel</source>
        <translation>Annuller</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Open large…</source>
        <translation>Åbn stort…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The plot in a window of its own, as large as the screen allows</source>
        <translation>Grafen i sit eget vindue, så stort som skærmen tillader</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Error and energy drift against CPU time for every integrator (1 repeat, tolerances 1e-3…1e-10).</source>
        <translation>Fejl og energidrift som funktion af CPU-tid for hver integrator (1 gentagelse, tolerancer 1e-3…1e-10).</translation>
    </message>
    <message>
        <location line="+39" />
        <source>Work–precision: %1</source>
        <translation>Beregningsarbejde–præcision: %1</translation>
    </message>
    <message>
        <location line="+42" />
        <source>cancelled</source>
        <translation>annulleret</translation>
    </message>
    <message numerus="yes">
        <location line="+13" />
        <source>Done: %n run(s).</source>
        <translation>
            <numerusform>Færdig: %n kørsel.</numerusform>
            <numerusform>Færdig: %n kørsler.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2" />
        <source>Stopped: %1</source>
        <translation>Stoppet: %1</translation>
    </message>
    <message>
        <location line="+19" />
        <source>no work–precision result yet: run the sweep first</source>
        <translation>endnu intet resultat for beregningsarbejde–præcision: kør gennemløbet først</translation>
    </message>
</context>
<context>
    <name>ll::ui::DerivationCanvas</name>
    <message>
        <location filename="../../ui/window/derivation_canvas.hpp" line="+212" />
        <source>Copy %1 as LaTeX</source>
        <translation>Kopiér %1 som LaTeX</translation>
    </message>
</context>
<context>
    <name>ll::ui::DerivationView</name>
    <message>
        <location line="-184" />
        <source>equation %1</source>
        <translation>ligning %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>closed loop %1</source>
        <translation>lukket sløjfe %1</translation>
    </message>
</context>
</TS>
