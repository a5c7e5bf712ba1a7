PART
lawn
1-1-0
END
