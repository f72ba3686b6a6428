"""The measure of every claim, one module per paper (:mod:`.sticky`, :mod:`.ltp`, :mod:`.blob`) and for the
cross-method study (:mod:`.cross`)."""
