package org.tensim.app.scenetest;

import java.io.PrintWriter;
import java.nio.file.Path;
import org.junit.platform.engine.TestExecutionResult;
import org.junit.platform.engine.discovery.DiscoverySelectors;
import org.junit.platform.launcher.EngineFilter;
import org.junit.platform.launcher.Launcher;
import org.junit.platform.launcher.LauncherDiscoveryRequest;
import org.junit.platform.launcher.TestExecutionListener;
import org.junit.platform.launcher.TestIdentifier;
import org.junit.platform.launcher.TestPlan;
import org.junit.platform.launcher.core.LauncherDiscoveryRequestBuilder;
import org.junit.platform.launcher.core.LauncherFactory;
import org.junit.platform.launcher.listeners.SummaryGeneratingListener;
import org.junit.platform.launcher.listeners.TestExecutionSummary;
import org.junit.platform.reporting.legacy.xml.LegacyXmlReportGeneratingListener;

/**
 * Runs {@link SceneSuite} over a folder through the JUnit Platform Launcher, with the Jupiter engine only: each
 * test's verdict is printed as it ends, and the legacy XML reporting listener writes the JUnit XML report
 * ({@code TEST-junit-jupiter.xml}: one {@code testcase} a test, a {@code failure} with the message for each
 * failed one), the format CI servers read.
 */
public final class SceneTestLauncher {
    /** The counts of a launch. */
    public record Result(long passed, long failed, long skipped) {
        /** "N passed, N failed", and ", N skipped" when a scene's data is absent. */
        public String line() {
            return passed + " passed, " + failed + " failed" + (skipped > 0 ? ", " + skipped + " skipped" : "");
        }
    }

    private SceneTestLauncher() {
    }

    /**
     * Runs the scene files under {@code dir}, their runs written under {@code out}, the XML reports into
     * {@code reports}; prints each test's verdict on {@code print}.
     */
    public static Result run(Path dir, Path out, Path reports, boolean overwrite, PrintWriter print) {
        LauncherDiscoveryRequest request = LauncherDiscoveryRequestBuilder.request()
                .selectors(DiscoverySelectors.selectClass(SceneSuite.class))
                .filters(EngineFilter.includeEngines("junit-jupiter"))
                .configurationParameter(SceneSuite.DIR, dir.toString())
                .configurationParameter(SceneSuite.OUT, out.toString())
                .configurationParameter(SceneSuite.OVERWRITE, Boolean.toString(overwrite))
                .build();
        Launcher launcher = LauncherFactory.create();
        SummaryGeneratingListener summary = new SummaryGeneratingListener();
        LegacyXmlReportGeneratingListener xml = new LegacyXmlReportGeneratingListener(reports, print);
        launcher.execute(request, summary, xml, new Printer(print));
        TestExecutionSummary s = summary.getSummary();
        // A container that fails (the folder cannot be searched) is a failure too, not a test fewer. A test
        // aborted is a scene skipped because a file it names is absent (SceneSuite), printed with its name.
        long failed = s.getTestsFailedCount() + s.getContainersFailedCount();
        print.flush();
        return new Result(s.getTestsSucceededCount(), failed, s.getTestsAbortedCount() + s.getTestsSkippedCount());
    }

    /** One line per finished test (and per failed container): its verdict, file and name, and why it failed. */
    private static final class Printer implements TestExecutionListener {
        private final PrintWriter out;
        private TestPlan plan;

        Printer(PrintWriter out) {
            this.out = out;
        }

        @Override
        public void testPlanExecutionStarted(TestPlan testPlan) {
            plan = testPlan;
        }

        @Override
        public void executionFinished(TestIdentifier id, TestExecutionResult result) {
            boolean ok = result.getStatus() == TestExecutionResult.Status.SUCCESSFUL;
            boolean skipped = result.getStatus() == TestExecutionResult.Status.ABORTED;
            if (!id.isTest() && ok) {
                return;
            }
            String file = plan.getParent(id).filter(p -> p.getSource().isPresent() && !p.isTest())
                    .map(TestIdentifier::getDisplayName).orElse("");
            String why = result.getThrowable().map(t -> ": " + t.getMessage()).orElse("");
            out.println((ok ? "pass " : skipped ? "skip " : "FAIL ") + (file.isEmpty() ? "" : file + " > ")
                    + id.getDisplayName() + (ok ? "" : why));
            out.flush();
        }
    }
}
