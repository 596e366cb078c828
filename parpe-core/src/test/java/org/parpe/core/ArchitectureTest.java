package org.parpe.core;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.Architectures.layeredArchitecture;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;

import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.junit.AnalyzeClasses;
import com.tngtech.archunit.junit.ArchTest;
import com.tngtech.archunit.lang.ArchRule;

/**
 * The shape of the core (docs/architecture.md, STYLE.md "One direction of dependencies"): its
 * packages form no cycle, each stage of the pipeline uses only the stages before it, and it
 * uses no other module of PARPE and none of the libraries kept to them.
 */
@AnalyzeClasses(packages = "org.parpe.core", importOptions = ImportOption.DoNotIncludeTests.class)
class ArchitectureTest {
    /**
     * Issue 32, item 4: one slice per package, by its full name, so the root package and every
     * subpackage count ({@code org.parpe.core.(*)..} left the root out and merged subpackages).
     */
    @ArchTest
    static final ArchRule PACKAGES_FORM_NO_CYCLE = slices().matching("org.parpe.(**)").should().beFreeOfCycles();

    @ArchTest
    static final ArchRule PIPELINE_LAYERS = layeredArchitecture().consideringOnlyDependenciesInLayers()
            .layer("diag").definedBy("org.parpe.core.diag..")
            .layer("lang").definedBy("org.parpe.core.lang..")
            .layer("sensor").definedBy("org.parpe.core.sensor..")
            .layer("io").definedBy("org.parpe.core.io..")
            .layer("xml").definedBy("org.parpe.core.xml..")
            .layer("expr").definedBy("org.parpe.core.expr..")
            .layer("model").definedBy("org.parpe.core.model..")
            .layer("load").definedBy("org.parpe.core.load..")
            .layer("edit").definedBy("org.parpe.core.edit..")
            .layer("print").definedBy("org.parpe.core.print..")
            .layer("run").definedBy("org.parpe.core.run..")
            .layer("export").definedBy("org.parpe.core.export..")
            .layer("diagram").definedBy("org.parpe.core.diagram..")
            .layer("plot").definedBy("org.parpe.core.plot..")
            .whereLayer("plot").mayNotBeAccessedByAnyLayer()
            .whereLayer("diagram").mayNotBeAccessedByAnyLayer()
            .whereLayer("export").mayNotBeAccessedByAnyLayer()
            .whereLayer("load").mayOnlyBeAccessedByLayers("diagram")
            .whereLayer("print").mayOnlyBeAccessedByLayers("diagram")
            .whereLayer("edit").mayOnlyBeAccessedByLayers("print", "diagram")
            .whereLayer("run").mayOnlyBeAccessedByLayers("diagram", "export", "plot")
            .whereLayer("model").mayOnlyBeAccessedByLayers("load", "print", "run", "export", "diagram")
            .whereLayer("expr").mayOnlyBeAccessedByLayers("model", "load", "print", "run", "export", "diagram")
            .whereLayer("xml").mayOnlyBeAccessedByLayers("expr", "model", "load", "edit", "print", "run", "export",
                    "diagram")
            .whereLayer("sensor").mayOnlyBeAccessedByLayers("expr", "load", "run", "export", "diagram", "plot")
            .whereLayer("lang").mayOnlyBeAccessedByLayers("xml", "expr", "model", "load", "edit", "print", "run",
                    "export", "diagram");

    @ArchTest
    static final ArchRule NO_OTHER_MODULE_OR_THEIR_LIBRARIES = noClasses().that().resideInAPackage("org.parpe.core..")
            .should().dependOnClassesThat().resideInAnyPackage("org.parpe.sim..", "org.parpe.serial..",
                    "org.parpe.cli..", "org.parpe.gui..", "org.eclipse..", "org.ode4j..", "com.fazecast..",
                    // issue 19, item 10: the configuration files are read with the scripts' StAX parser
                    "com.fasterxml.jackson..");
}
