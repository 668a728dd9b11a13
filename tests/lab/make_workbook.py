"""Writes the .xlsx workbooks of tests/lab/test_lab_files.cpp.

    make_workbook.py lab.xlsx       # openpyxl: a notes sheet, the readings, the sieves
    make_workbook.py shared.xlsx    # by hand: shared strings, as Excel and LibreOffice save
    make_workbook.py damaged.xlsx   # shared.xlsx with a cell reference past any column
    make_workbook.py bad.xlsx       # openpyxl: a temperature off the scale, sieves over the total

The first is what openpyxl (Debian's python3-openpyxl 3.0) saves: text as inline strings,
numbers, empty cells and rows, a text cell with a decimal comma. The second what Excel and
LibreOffice save: text as shared strings (one a rich string of two runs with a phonetic
guide), cells with and without references, a formula's cached value, a comment row and an
empty row above the header. Both hold test_lab_reduction.cpp's worked example: 50 g of Gs 2.70
soil at 22 C, composite correction 5 g/L, R = 42, 20, 10 at 2, 60 and 1440 min.
"""
import sys
import zipfile


def lab_workbook(path):
    import openpyxl

    book = openpyxl.Workbook()
    notes = book.active
    notes.title = "Notes"
    notes["A1"] = "Sample B-12, 50 g oven-dry, Gs 2.70"
    readings = book.create_sheet("Readings")
    readings.append(["time (min)", "R (g/L)", "T (\u00b0C)", "C (g/L)", "remark"])
    readings.append([2, 42, 22.0, 5, "stirred"])
    readings.append([])  # an empty row between readings
    readings.append([60, 20, "22,0", 5])  # typed as text, with a decimal comma
    readings.append([1440, 10, 22, 5, None])
    sieves = book.create_sheet("Sieves")
    sieves.append(["Sieve", "Opening (mm)", "Mass retained (g)"])
    for row in [["3/8 in", 9.5, 0], ["#4", 4.75, 12], ["#10", 2, 18], ["#40", 0.425, 30],
                ["#200", 0.075, 40], ["Pan", None, 100], ["Total", None, 200]]:
        sieves.append(row)
    book.save(path)


def bad_workbook(path):
    # Values a reader takes but a reduction refuses: errors must name the sheet and its row.
    import openpyxl

    book = openpyxl.Workbook()
    readings = book.active
    readings.title = "Readings"
    readings.append(["time (min)", "R (g/L)", "T (\u00b0C)", "C (g/L)"])
    readings.append([2, 42, 22, 5])
    readings.append([])  # an empty row: the sheet's row numbers are not the readings' count
    readings.append([60, 20, 99, 5])  # row 4: 99 C is off the water density formula
    sieves = book.create_sheet("Sieves")
    sieves.append(["Opening (mm)", "Mass retained (g)"])
    for row in [[4.75, 12], [2, 18], [0.425, 30], ["Total", 40]]:  # row 4 passes the total
        sieves.append(row)
    book.save(path)


def relationships(rid, kind, target):
    return f"""<?xml version="1.0" encoding="UTF-8"?>
<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">
<Relationship Id="{rid}" Type="http://schemas.openxmlformats.org/officeDocument/2006/relationships/{kind}" Target="{target}"/>
</Relationships>"""


def shared_workbook(path, damaged=False):
    # The smallest package a reader must take: content types, the workbook, its relations,
    # the shared strings and one sheet.
    parts = {
        "[Content_Types].xml": """<?xml version="1.0" encoding="UTF-8"?>
<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types">
<Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/>
<Default Extension="xml" ContentType="application/xml"/>
<Override PartName="/xl/workbook.xml" ContentType="application/vnd.openxmlformats-officedocument.spreadsheetml.sheet.main+xml"/>
<Override PartName="/xl/sharedStrings.xml" ContentType="application/vnd.openxmlformats-officedocument.spreadsheetml.sharedStrings+xml"/>
<Override PartName="/xl/worksheets/data.xml" ContentType="application/vnd.openxmlformats-officedocument.spreadsheetml.worksheet+xml"/>
</Types>""",
        "_rels/.rels": relationships("rId1", "officeDocument", "xl/workbook.xml"),
        "xl/workbook.xml": """<?xml version="1.0" encoding="UTF-8"?>
<workbook xmlns="http://schemas.openxmlformats.org/spreadsheetml/2006/main" xmlns:r="http://schemas.openxmlformats.org/officeDocument/2006/relationships">
<sheets><sheet name="Hydrometer" sheetId="1" r:id="rIdSheet"/></sheets>
</workbook>""",
        # An absolute target, as some writers give it.
        "xl/_rels/workbook.xml.rels": relationships("rIdSheet", "worksheet",
                                                    "/xl/worksheets/data.xml"),
        "xl/sharedStrings.xml": """<?xml version="1.0" encoding="UTF-8"?>
<sst xmlns="http://schemas.openxmlformats.org/spreadsheetml/2006/main" count="3" uniqueCount="3">
<si><r><t xml:space="preserve">elapsed </t></r><r><rPr><b/></rPr><t>time, s</t></r><rPh sb="0" eb="1"><t>ignored</t></rPh></si>
<si><t>R [g/L]</t></si>
<si><t>Temperature [C]</t></si>
</sst>""",
        "xl/worksheets/data.xml": """<?xml version="1.0" encoding="UTF-8"?>
<worksheet xmlns="http://schemas.openxmlformats.org/spreadsheetml/2006/main"><sheetData>
<row r="1"><c t="inlineStr"><is><t># exported by the balance</t></is></c></row>
<row r="3"><c t="s"><v>0</v></c><c t="s"><v>1</v></c><c t="s"><v>2</v></c><c t="inlineStr"><is><t>Cc</t></is></c></row>
<row r="4"><c><v>120</v></c><c><v>42</v></c><c><v>22</v></c><c><v>5</v></c></row>
<row r="5"><c r="A5"><v>3600</v></c><c r="B5"><v>20</v></c><c r="C5"><v>22</v></c><c r="D5"><v>5</v></c></row>
<row r="6"><c r="A6"><v>86400</v></c><c r="B6" t="str"><f>10*1</f><v>10</v></c><c r="C6"><v>22</v></c><c r="D6"><v>5</v></c></row>
</sheetData></worksheet>""",
    }
    if damaged:  # a reader that trusts the reference overflows or allocates without bound
        parts["xl/worksheets/data.xml"] = parts["xl/worksheets/data.xml"].replace(
            '<c r="A5">', '<c r="ZZZZZZZZZZZZZZZZ5">')
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as z:
        for name, text in parts.items():
            z.writestr(name, text)


if __name__ == "__main__":
    out = sys.argv[1]
    if out.endswith("bad.xlsx"):
        bad_workbook(out)
    elif out.endswith("shared.xlsx") or out.endswith("damaged.xlsx"):
        shared_workbook(out, damaged=out.endswith("damaged.xlsx"))
    else:
        lab_workbook(out)
