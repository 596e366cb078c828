package org.parpe.core.io;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/**
 * Cells a spreadsheet would evaluate (OWASP "CSV Injection": = + - @ tab CR) get an apostrophe;
 * numbers, negative ones included, stay numbers.
 */
class CsvCellsTest {
    @Test
    void formulasAreNeutralisedAndNumbersKept() {
        assertEquals("'=HYPERLINK(\"http://x\")", CsvCells.safe("=HYPERLINK(\"http://x\")"));
        assertEquals("'+1+cmd|' /C calc'!A0", CsvCells.safe("+1+cmd|' /C calc'!A0"));
        assertEquals("'-2+3", CsvCells.safe("-2+3"));
        assertEquals("'@SUM(A1)", CsvCells.safe("@SUM(A1)"));
        assertEquals("'\t=1", CsvCells.safe("\t=1"));
        assertEquals("'\r=1", CsvCells.safe("\r=1"));
        assertEquals("'-", CsvCells.safe("-"));
        for (String n : new String[] {"-1.5", "+2", "-3e-4", "-.5", "0.000000", "12", "", "x.xml:3:4: error"}) {
            assertEquals(n, CsvCells.safe(n));
        }
    }

    @Test
    void aLineKeepsItsQuotingAndOnlyItsFormulasChange() {
        String good = "0,4,0,0,1,-1.5,2.000000,,0,\"x.xml:1:1: error: bad, very\"";
        assertEquals(good, CsvCells.safeLine(good));
        assertEquals("0,'=1+1,\"'=cmd|\"\"x\"\"\",'-x", CsvCells.safeLine("0,=1+1,\"=cmd|\"\"x\"\"\",-x"));
        assertEquals("\"'=a,b\"", CsvCells.safeLine("\"=a,b\""));
    }
}
