<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
<context>
    <name>imudesk::ui::RawBytesView</name>
    <message numerus="yes">
        <location filename="../ui/raw_bytes_view.cpp" line="+196"/>
        <source>… %n read(s) or write(s) not shown (the log dropped them before this view caught up) …</source>
        <translation>
            <numerusform>… %n read or write not shown (the log dropped them before this view caught up) …</numerusform>
            <numerusform>… %n reads or writes not shown (the log dropped them before this view caught up) …</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>… %n byte(s) not shown (more arrived than the view holds) …</source>
        <translation>
            <numerusform>… %n byte not shown (more arrived than the view holds) …</numerusform>
            <numerusform>… %n bytes not shown (more arrived than the view holds) …</numerusform>
        </translation>
    </message>
</context>
</TS>
