package org.parpe.gui;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.classes;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;

import com.tngtech.archunit.base.DescribedPredicate;
import com.tngtech.archunit.core.domain.JavaClass;
import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.junit.AnalyzeClasses;
import com.tngtech.archunit.junit.ArchTest;
import com.tngtech.archunit.lang.ArchRule;
import java.lang.reflect.RecordComponent;
import java.util.Arrays;
import java.util.List;

/**
 * Issue 32, item 1: one edit layer ({@code org.parpe.core.edit}) over every module the IDE
 * sees. A view that changes a script's text hands the editor the one replacement record, and
 * nothing finds places in script text with regular expressions but the XML reader and the
 * editor's forgiving scanner (which keeps completion working while the script is not
 * well-formed); the rest finds them by the loader's source spans. The command line, on the IDE's
 * class path for its picocli texts ({@code cli.text}), is left out as before: its rules are its
 * own ({@code ModuleLayersTest}), and its plotting library is not on this class path.
 */
@AnalyzeClasses(packages = {"org.parpe.core", "org.parpe.sim", "org.parpe.serial", "org.parpe.gui"},
        importOptions = ImportOption.DoNotIncludeTests.class)
class EditLayerTest {
    /** A record of an offset, a length or end, and the text that replaces them: a replacement. */
    private static final DescribedPredicate<JavaClass> REPLACEMENT_SHAPED = DescribedPredicate.describe(
            "records of two ints and a String (a replacement of a range of text)", c -> {
                Class<?> k = c.reflect();
                if (!k.isRecord()) {
                    return false;
                }
                List<Class<?>> types = Arrays.stream(k.getRecordComponents()).map(RecordComponent::getType)
                        .<Class<?>>map(t -> t).toList();
                return types.size() == 3 && types.stream().filter(t -> t == int.class).count() == 2
                        && types.contains(String.class);
            });

    @ArchTest
    static final ArchRule ONE_REPLACEMENT_RECORD = classes().that(REPLACEMENT_SHAPED).should()
            .haveFullyQualifiedName("org.parpe.core.edit.Replacement");

    /**
     * The classes allowed regular expressions, each over something that is not a script's text:
     * the XML reader of flat files, the editor's forgiving scanner, attribute values, CSV cells,
     * stimulus and world files, the head line of a grading shard's file, command names in help
     * pages. Sensor references inside expressions are read by {@code core.sensor.SensorRef}, by hand.
     */
    @ArchTest
    static final ArchRule NO_PATTERNS_OVER_SCRIPT_TEXT = noClasses().that().resideInAPackage("org.parpe..")
            .and().doNotHaveFullyQualifiedName("org.parpe.core.xml.FlatXmlFile")
            .and().doNotHaveFullyQualifiedName("org.parpe.gui.editor.NameIndex")
            .and().doNotHaveFullyQualifiedName("org.parpe.core.load.Attrs")
            .and().doNotHaveFullyQualifiedName("org.parpe.core.io.CsvCells")
            .and().doNotHaveFullyQualifiedName("org.parpe.core.run.StimulusParser")
            .and().doNotHaveFullyQualifiedName("org.parpe.sim.sweep.SweepCsv")
            .and().doNotHaveFullyQualifiedName("org.parpe.core.text.BundleCheck") // placeholders in bundle texts
            .and().doNotHaveFullyQualifiedName("org.parpe.core.text.ProseLiterals") // prose in Java string literals (text tests)
            .and().doNotHaveFullyQualifiedName("org.parpe.sim.world.WorldReader")
            .and().doNotHaveFullyQualifiedName("org.parpe.sim.grade.GradeShard")
            .and().doNotHaveFullyQualifiedName("org.parpe.gui.help.CommandNames")
            .should().dependOnClassesThat().resideInAPackage("java.util.regex..");

    /**
     * Issue 32, item 3 ("resolve once"): the loader binds every instance to its automaton and
     * group and every {@code <main>} entry to its behavior, so no later stage looks a name up in
     * the program again. Looking up is left to loading, to editing (is a new name free?) and to
     * the places that resolve a name the user typed or chose (a command-line option, a
     * dialog's field, a view's chooser).
     */
    @ArchTest
    static final ArchRule NAMES_ARE_LOOKED_UP_ONLY_BY_LOADING_EDITING_AND_USER_INPUT = classes()
            .that().resideInAPackage("org.parpe..")
            .and().resideOutsideOfPackages("org.parpe.core.load..", "org.parpe.core.model..", "org.parpe.core.edit..")
            .and().haveSimpleNameNotEndingWith("Edits")
            .and(DescribedPredicate.not(NameLookups.RESOLVE_USER_INPUT))
            .should(NameLookups.NOT_LOOK_A_NAME_UP);
}
