package org.parpe.gui;

import static com.tngtech.archunit.base.DescribedPredicate.describe;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.classes;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.methods;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;

import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.junit.AnalyzeClasses;
import com.tngtech.archunit.junit.ArchTest;
import com.tngtech.archunit.lang.ArchRule;
import org.parpe.gui.app.IdeWindow;

/**
 * The IDE's packages, each one concept (issue 19, item 9: {@code gui.app} was a grab-bag of twenty
 * classes): they form no cycle, and only the window's own package and {@code Main} know the window;
 * the features and the command-line automation reach it through their host interfaces. The
 * no-cycle rule slices by full package name, so the root package {@code org.parpe.gui} counts too
 * (issue 32, item 4).
 */
@AnalyzeClasses(packages = "org.parpe.gui", importOptions = ImportOption.DoNotIncludeTests.class)
class GuiPackagesTest {
    @ArchTest
    static final ArchRule IDE_PACKAGES_FORM_NO_CYCLE = slices().matching("org.parpe.(**)").should()
            .beFreeOfCycles();

    @ArchTest
    static final ArchRule ONLY_THE_TOP_KNOWS_THE_WINDOW = noClasses().that().resideInAPackage("org.parpe.gui.(*)..")
            .and().resideOutsideOfPackage("org.parpe.gui.app..")
            .should().dependOnClassesThat().resideInAPackage("org.parpe.gui.app..");

    /**
     * Issue 32, item 2: the IDE loads PARSL text in one place, the open script's document
     * ({@code ScriptDocument}, which loads each version of the editor's text once); every view
     * reads it there instead of loading the text again. (It failed on the tree before: the sweep
     * dialog, its runner and "apply best" called the loader themselves.)
     */
    @ArchTest
    static final ArchRule ONLY_THE_DOCUMENT_LOADS_SCRIPTS = noClasses()
            .that().haveNameNotMatching("org\\.parpe\\.gui\\.editor\\.ScriptDocument(\\$.*)?")
            .should().dependOnClassesThat().haveFullyQualifiedName("org.parpe.core.load.ScriptLoader");

    /**
     * Issue 32's acceptance: a feature's package reaches the window through a narrow host
     * interface of its own ({@code HardwareHost}, {@code PoseHost}, {@code RobotHost}; the automation's
     * {@code AutomationHost} and {@code BenchHost}), and only
     * the window's package implements one, so a feature never hands another feature's object in
     * as the window. (ArchUnit fails a rule that no class meets, so this one cannot pass empty.)
     */
    @ArchTest
    static final ArchRule ONLY_THE_WINDOW_IMPLEMENTS_THE_HOST_INTERFACES = classes().that().areNotInterfaces()
            .and().implement(describe("an IDE host interface (org.parpe.gui..*Host)",
                    i -> i.getName().startsWith("org.parpe.gui.") && i.getSimpleName().endsWith("Host")))
            .should().resideInAPackage("org.parpe.gui.app..");

    /**
     * Issue 32, item 2: the window hands out no part of itself. Besides its constructor it offers
     * {@code Main} what starts and ends it ({@code open}, {@code closed}, {@code internalError} for
     * the event loop) and itself as the automation's host ({@code automated}); every feature and the
     * automation reach it through a host interface, and tests of other packages through
     * {@code IdeAccess}. (It failed on the tree before: fifteen public getters, {@code shell()} to
     * {@code validations()}, and {@code showPosePanel()}.)
     */
    @ArchTest
    static final ArchRule THE_WINDOW_HAS_NO_PUBLIC_GETTERS = methods().that().areDeclaredIn(IdeWindow.class).and().arePublic()
            .should().haveNameMatching("open|closed|internalError|automated");
}
