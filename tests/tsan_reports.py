#!/usr/bin/env python3
# Sorts the reports of a ThreadSanitizer run (cmake -DIMUDESK_TSAN=ON, tests/tsan.supp) by what
# they are: a value handed over by a queued signal or QMetaObject::invokeMethod, an object freed
# after its thread was joined, Qt Gui's own worker threads; what fits none of these is printed
# with its ImuDesk frames, to be read by hand. Usage: tsan_reports.py LOG...
import re,sys,collections
marks=['QMetaType::construct','getCopyCtr','QObject::event','QMetaCallEvent','invokeMethod','QSlotObject','QMetaObject::activate','cxa_at_exit','QFunctorSlotObject','QCallableObject','doActivate','queued_activate']
tot=collections.Counter()
for f in sys.argv[1:]:
    txt=open(f).read()
    blocks=txt.split('WARNING: ThreadSanitizer:')[1:]
    cls=collections.Counter(); other=[]
    for b in blocks:
        b=b.split('SUMMARY:')[0]
        acc=re.split(r'\n  (?=(?:Location|Thread|Mutex))', b)[0]
        if 'libQt6Gui.so' in acc and 'QThread::start' in b and 'paint' in b: cls['Qt Gui worker threads (image/paint)']+=1; continue
        if any(m in acc for m in marks): cls['queued hand-over (signal / invokeMethod)']+=1; continue
        if re.search(r'Thread T\d+ \(tid=\d+, finished\)', b) and ('~' in acc or 'deallocate' in acc or 'operator delete' in acc or 'free' in acc): cls['freed after the thread was joined (QThread::wait)']+=1; continue
        if 'operator delete' in acc or '~' in acc:
            cls['freed after a blocking queued call / join (unclassified destructor)']+=1; other.append(b); continue
        cls['other']+=1; other.append(b)
    print('==',f,len(blocks),dict(cls))
    tot.update(cls)
    for b in other[:3]:
        fr=re.findall(r'#\d+ (\S+)', b)
        print('   ', [x[:80] for x in fr if 'imudesk' in x or 'Tst' in x][:4], '| finished' if 'finished)' in b else '')
print(dict(tot))
